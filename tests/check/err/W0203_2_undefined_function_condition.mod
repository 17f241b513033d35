! expect: W0203 line 5
! an undefined function as IF condition (no E0310: its type is unknown)
MODULE W0203_2
  PROC main()
    IF IsReady() THEN
      TPWrite "ready";
    ENDIF
  ENDPROC
ENDMODULE
