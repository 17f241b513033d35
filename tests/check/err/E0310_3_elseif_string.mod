! expect: E0310 line 9
! ELSEIF with a string condition
MODULE E0310_3
  VAR num n;
  VAR string s;
  PROC main()
    IF n > 0 THEN
      n := 0;
    ELSEIF s THEN
      n := 1;
    ENDIF
  ENDPROC
ENDMODULE
