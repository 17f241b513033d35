MODULE motion_trigg_data
  ! TriggDataValid, TriggDataCopy and TriggDataReset (RAPID overview 1.8, "TriggDataCopy",
  ! "TriggDataReset", "TriggDataValid", RobotWare 6.02): a triggdata is valid once a
  ! trigger instruction has defined it and no longer after TriggDataReset; a copy holds
  ! the same trigger, so the TriggL with the copy still fires the interrupt on its path.
  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR triggdata t1;
  VAR triggdata t2;
  VAR intnum mark;

  PROC main()
    TPWrite "t1 valid " \Bool:=TriggDataValid(t1);
    CONNECT mark WITH on_mark;
    TriggInt t1, 10 \Start, mark;
    TPWrite "t1 valid " \Bool:=TriggDataValid(t1);
    TriggDataCopy t1, t2;
    TriggDataReset t1;
    TPWrite "t1 valid " \Bool:=TriggDataValid(t1);
    TPWrite "t2 valid " \Bool:=TriggDataValid(t2);
    MoveJ p0, v1000, fine, tool0;
    TriggL Offs(p0, 100, 0, 0), v100, t2, fine, tool0;
    TPWrite "arrived";
    IDelete mark;
  ENDPROC

  TRAP on_mark
    TPWrite "mark";
  ENDTRAP
ENDMODULE
