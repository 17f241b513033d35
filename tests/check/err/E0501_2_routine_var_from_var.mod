! expect: E0501 line 6
! a routine VAR initialised from another routine VAR
MODULE E0501_2
  PROC main()
    VAR num a := 1;
    VAR num b := a;
    TPWrite "b: " \Num:=b;
  ENDPROC
ENDMODULE
