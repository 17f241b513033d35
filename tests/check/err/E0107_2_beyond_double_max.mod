! expect: E0107 line 6
! 1.8E308 is above the largest double (dnum context, so not E0314)
MODULE E0107_2
  VAR dnum d;
  PROC main()
    d := 1.8E308;
  ENDPROC
ENDMODULE
