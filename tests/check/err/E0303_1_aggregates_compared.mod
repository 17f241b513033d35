! expect: E0303 line 5
! two aggregates compared: nothing gives them a type
MODULE E0303_1
  PROC main()
    IF [1,2,3] = [1,2,3] THEN
      TPWrite "same";
    ENDIF
  ENDPROC
ENDMODULE
