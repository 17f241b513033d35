! expect: E0121 line 6
! TEST without ENDTEST
MODULE E0121_5
  VAR num n;
  PROC main()
    TEST n
    CASE 1:
      n := 2;
    DEFAULT:
      n := 0;
  ENDPROC
ENDMODULE
