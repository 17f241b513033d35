! expect: E0308 line 8
! a signal assigned (reading one is fine)
MODULE E0308_2
  VAR signaldi di1;
  VAR signaldo do1;
  PROC main()
    IF di1 = 1 THEN
      do1 := 1;
    ENDIF
  ENDPROC
ENDMODULE
