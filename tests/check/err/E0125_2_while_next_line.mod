! expect: E0125 line 7
! a WHILE as the statement of a compact IF, on the next line: reported at WHILE
MODULE E0125_2
  VAR num n;
  PROC main()
    IF n > 0
      WHILE n < 10 DO
        n := n + 1;
      ENDWHILE
  ENDPROC
ENDMODULE
