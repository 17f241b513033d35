! expect: E0309 line 7
! an assignment to the FOR loop variable
MODULE E0309_2
  VAR num n;
  PROC main()
    FOR i FROM 1 TO 3 DO
      i := 5;
      n := n + 1;
    ENDFOR
  ENDPROC
ENDMODULE
