! expect: E0310 line 6
! IF with a num condition
MODULE E0310_1
  VAR num n;
  PROC main()
    IF n THEN
      n := 0;
    ENDIF
  ENDPROC
ENDMODULE
