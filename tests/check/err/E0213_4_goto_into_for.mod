! expect: E0213 line 6
! a GOTO from before a FOR into its body
MODULE E0213_4
  VAR num n;
  PROC main()
    GOTO step_in;
    FOR i FROM 1 TO 3 DO
    step_in:
      n := n + 1;
    ENDFOR
  ENDPROC
ENDMODULE
