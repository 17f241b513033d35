! expect: E0125 line 6
! a FOR as the statement of a compact IF
MODULE E0125_1
  VAR num n;
  PROC main()
    IF n > 0 FOR i FROM 1 TO 3 DO
      n := n + i;
    ENDFOR
  ENDPROC
ENDMODULE
