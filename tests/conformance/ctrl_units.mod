MODULE ctrl_units
  ! Tasks and mechanical units (manual 1.17, 1.20). A program run alone is the
  ! NORMAL motion task T_ROB1, selected in the Task Selection Panel
  ! (TSP_STATUS_ACT), with motion planner 1 and robot ROB_1 (ROB_ID is the task's
  ! own robot). The duty time counter counts the controller time in whole hours
  ! (docs/semantics.md, uncertain): 0 at the start, 2 after 2.5 h.
  VAR num status;
  VAR string text;

  PROC ShowUnit(VAR mecunit unit)
    TPWrite "through a parameter " + GetMecUnitName(unit);
  ENDPROC

  PROC main()
    TPWrite "active " \Bool:=(GetTSPStatus("T_ROB1") = TSP_STATUS_ACT);
    TPWrite "by taskid " \Bool:=(GetTSPStatus(T_ROB1Id) = TSP_STATUS_ACT);
    TPWrite "planner " \Num:=MotionPlannerNo();
    TPWrite GetMecUnitName(ROB_1);
    TPWrite "ROB_ID is " + GetMecUnitName(ROB_ID);
    ShowUnit ROB_1;
    TPWrite "duty time " + GetServiceInfo(ROB_1 \DutyTimeCnt);
    WaitTime 9000;
    TPWrite "duty time " + GetServiceInfo(ROB_1 \DutyTimeCnt);
    status := GetTSPStatus("T_NOSUCH");
    text := GetServiceInfo(ROB_1);
    TPWrite "done";
  ERROR
    IF ERRNO = ERR_TASKNAME THEN
      TPWrite "ERR_TASKNAME";
    ELSEIF ERRNO = ERR_ARGVALERR THEN
      TPWrite "ERR_ARGVALERR";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
