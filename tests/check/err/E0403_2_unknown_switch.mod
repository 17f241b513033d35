! expect: E0403 line 8
! a switch the procedure does not declare
MODULE E0403_2
  PROC open_gripper(\switch slow)
    IF Present(slow) TPWrite "slow";
  ENDPROC
  PROC main()
    open_gripper \Fast;
  ENDPROC
ENDMODULE
