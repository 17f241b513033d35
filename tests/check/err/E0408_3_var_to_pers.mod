! expect: E0408 line 11
! a VAR passed to a PERS parameter
MODULE E0408_3
  PERS num counter := 0;
  VAR num local_n;
  PROC bump(PERS num p)
    p := p + 1;
  ENDPROC
  PROC main()
    bump counter;
    bump local_n;
  ENDPROC
ENDMODULE
