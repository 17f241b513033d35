MODULE ctrl_sysdata_errors
  ! Errors of GetSysData / SetSysData, each taken by the handler (TRYNEXT goes on):
  ! a task the system does not have is ERR_TASKNAME (manual 1.17); an \ObjectName
  ! naming no data object is ERR_SYM_ACCESS and one naming data of another type
  ! ERR_SYMBOL_TYPE, as GetDataVal/SetDataVal report them; data that is no
  ! tooldata, wobjdata or loaddata is ERR_ARGVALERR (both uncertain,
  ! docs/semantics.md). After the failed calls tool0 is still the active tool.
  PERS tooldata tRead := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata wTable := [FALSE, TRUE, "", [[100, 200, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  PERS num count := 0;
  VAR string name;

  PROC main()
    GetSysData \TaskName:="T_NOSUCH", tRead;
    SetSysData tRead \ObjectName:="tNowhere";
    SetSysData tRead \ObjectName:="wTable";
    GetSysData count;
    SetSysData count;
    GetSysData tRead \ObjectName:=name;
    TPWrite "active " + name;
  ERROR
    IF ERRNO = ERR_TASKNAME THEN
      TPWrite "ERR_TASKNAME";
    ELSEIF ERRNO = ERR_SYM_ACCESS THEN
      TPWrite "ERR_SYM_ACCESS";
    ELSEIF ERRNO = ERR_SYMBOL_TYPE THEN
      TPWrite "ERR_SYMBOL_TYPE";
    ELSEIF ERRNO = ERR_ARGVALERR THEN
      TPWrite "ERR_ARGVALERR";
    ELSE
      TPWrite "other error";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
