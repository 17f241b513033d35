! expect: E0506 line 5
! LOCAL on a routine variable
MODULE E0506_1
  PROC main()
    LOCAL VAR num v;
    TPWrite "main";
  ENDPROC
ENDMODULE
