! expect: E0121 line 7
! IF without ENDIF - reported on the line of IF
MODULE E0121_1
  VAR num n;
  PROC main()
    n := 0;
    IF n > 0 THEN
      n := 1;
  ENDPROC
ENDMODULE
