MODULE ctrl_opmode_manual
  ! Run with --mode manual-reduced --speed-override 40 (ctrl_opmode_manual.args):
  ! OpMode gives OP_MAN_PROG, CSpeedOverride 40; with \CTask and SpeedRefresh 50
  ! the task runs at 40 * 50 / 100 = 20 %.
  PROC main()
    TPWrite "auto " \Bool:=(OpMode() = OP_AUTO);
    TPWrite "manual reduced " \Bool:=(OpMode() = OP_MAN_PROG);
    TPWrite "override " \Num:=CSpeedOverride();
    SpeedRefresh 50;
    TPWrite "task override " \Num:=CSpeedOverride(\CTask);
    IF OpMode() <> OP_AUTO THEN
      TPWrite "reduced speed: check the path before running in auto";
    ENDIF
  ENDPROC
ENDMODULE
