! expect: E0405 line 5
! Stop \NoRegain is a switch
MODULE E0405_2
  PROC main()
    Stop \NoRegain:=TRUE;
  ENDPROC
ENDMODULE
