! expect: E0405 line 8
! a value given to a switch
MODULE E0405_1
  PROC open_gripper(\switch fast)
    IF Present(fast) TPWrite "fast";
  ENDPROC
  PROC main()
    open_gripper \fast:=1;
  ENDPROC
ENDMODULE
