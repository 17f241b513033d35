! expect: E0307 line 7
! clock values compared with =
MODULE E0307_1
  VAR clock c1;
  VAR clock c2;
  PROC main()
    IF c1 = c2 THEN
      TPWrite "same";
    ENDIF
  ENDPROC
ENDMODULE
