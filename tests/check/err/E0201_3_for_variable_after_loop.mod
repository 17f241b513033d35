! expect: E0201 line 9
! the FOR variable does not exist after the loop
MODULE E0201_3
  VAR num n;
  PROC main()
    FOR i FROM 1 TO 3 DO
      n := n + i;
    ENDFOR
    n := i;
  ENDPROC
ENDMODULE
