MODULE ctrl_opmode_full
  ! Run with --mode manual-full --speed-override 1 (ctrl_opmode_full.args).
  PROC main()
    TPWrite "manual full " \Bool:=(OpMode() = OP_MAN_TEST);
    TPWrite "override " \Num:=CSpeedOverride();
  ENDPROC
ENDMODULE
