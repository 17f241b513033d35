! expect: E0406 line 5
! \Num is not a switch and needs a value
MODULE E0406_1
  PROC main()
    TPWrite "a" \Num;
  ENDPROC
ENDMODULE
