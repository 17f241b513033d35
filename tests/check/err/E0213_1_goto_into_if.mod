! expect: E0213 line 10
! a GOTO from after an IF into its body
MODULE E0213_1
  VAR num n;
  PROC main()
    IF n > 0 THEN
    inside:
      n := n - 1;
    ENDIF
    GOTO inside;
  ENDPROC
ENDMODULE
