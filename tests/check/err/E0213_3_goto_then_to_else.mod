! expect: E0213 line 7
! a GOTO from the THEN branch into the ELSE branch
MODULE E0213_3
  VAR num n;
  PROC main()
    IF n > 0 THEN
      GOTO other;
    ELSE
    other:
      n := 1;
    ENDIF
  ENDPROC
ENDMODULE
