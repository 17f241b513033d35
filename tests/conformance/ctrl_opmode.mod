MODULE ctrl_opmode
  ! OpMode reads the operating mode key and CSpeedOverride the operator's override
  ! (manual 1.17, 1.7). `rapid run` starts in automatic mode at 100 % unless
  ! --mode / --speed-override say otherwise (docs/semantics.md).
  PROC main()
    TPWrite "auto " \Bool:=(OpMode() = OP_AUTO);
    TPWrite "manual reduced " \Bool:=(OpMode() = OP_MAN_PROG);
    TPWrite "manual full " \Bool:=(OpMode() = OP_MAN_TEST);
    TPWrite "override " \Num:=CSpeedOverride();
    ! \CTask: the operator's override scaled by the task's SpeedRefresh (100 % here).
    TPWrite "task override " \Num:=CSpeedOverride(\CTask);
    SpeedRefresh 50;
    TPWrite "task override " \Num:=CSpeedOverride(\CTask);
    TPWrite "override " \Num:=CSpeedOverride();
  ENDPROC
ENDMODULE
