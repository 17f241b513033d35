! expect: E0302 line 7
! string + num is not defined
MODULE E0302_3
  VAR string s;
  VAR num n := 3;
  PROC main()
    s := "n = " + n;
  ENDPROC
ENDMODULE
