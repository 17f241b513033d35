! expect: E0205 line 5
! a routine with the name of module data in the same module
MODULE E0205_3
  VAR num work;
  PROC work()
    TPWrite "work";
  ENDPROC
ENDMODULE
