! expect: E0213 line 6
! a GOTO from before a WHILE into its body
MODULE E0213_2
  VAR num n;
  PROC main()
    GOTO body;
    WHILE n < 10 DO
    body:
      n := n + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
