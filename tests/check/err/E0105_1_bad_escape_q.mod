! expect: E0105 line 5
! \q is not an escape
MODULE E0105_1
  PROC main()
    TPWrite "bad \q escape";
  ENDPROC
ENDMODULE
