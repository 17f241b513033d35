MODULE load_pers_shared
  ! A global PERS declared in several modules of a task is one persistent (manual
  ! 1.2.2). A loaded module declaring one the task has shares it: the current value
  ! stays (its own initial value is not applied), its changes count for
  ! UnLoad \ErrIfChanged, and Save writes the shared value.
  PERS num shared_p := 7;
  VAR iodev f;
  VAR string line;
  PROC main()
    Open "HOME:/sp.mod", f \Write;
    Write f, "MODULE sp";
    Write f, "PERS num shared_p := 1;";
    Write f, "PROC sp_p() shared_p := shared_p + 1; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load "HOME:/sp.mod";
    TPWrite "after load " \Num:=shared_p;
    %"sp_p"%;
    TPWrite "after call " \Num:=shared_p;
    UnLoad \ErrIfChanged, "HOME:/sp.mod";
    Save "sp" \FilePath:="HOME:/sp2.mod";
    Open "HOME:/sp2.mod", f \Read;
    line := ReadStr(f);
    line := ReadStr(f);
    TPWrite line;
    Close f;
  ERROR
    TPWrite "notsaved " \Bool:=ERRNO = ERR_NOTSAVED;
    TRYNEXT;
  ENDPROC
ENDMODULE
