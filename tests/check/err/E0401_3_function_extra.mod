! expect: E0401 line 6
! Abs takes one argument
MODULE E0401_3
  VAR num n;
  PROC main()
    n := Abs(1, 2);
  ENDPROC
ENDMODULE
