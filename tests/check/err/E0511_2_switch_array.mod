! expect: E0511 line 4
! an array of switch
MODULE E0511_2
  PROC run(\switch flags{*})
    TPWrite "run";
  ENDPROC
ENDMODULE
