! expect: E0120 line 8
! without THEN the IF is a compact IF, so the ENDIF is stray
MODULE E0120_5
  VAR num n;
  PROC main()
    IF n > 1
      n := 2;
    ENDIF
  ENDPROC
ENDMODULE
