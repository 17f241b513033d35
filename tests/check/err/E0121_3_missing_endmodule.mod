! expect: E0121 line 3
! MODULE without ENDMODULE (end of file)
MODULE E0121_3
  VAR num n;
  PROC main()
    n := 1;
  ENDPROC
