MODULE task_ref_virtual_io
    ! Run with --virtual-io. GetTSPStatus takes its task either by name
    ! (\TaskName, a string) or by reference (\TaskRef, a taskid); the argument's
    ! type picks the parameter (manual 1.17). A program run alone is T_ROB1, active
    ! in the Task Selection Panel: both ways give TSP_STATUS_ACT. A signal the
    ! configuration lacks is taken as one (doLamp), as --virtual-io says.
    PROC main()
        TPWrite "by name " \Bool:=(GetTSPStatus("T_ROB1") = TSP_STATUS_ACT);
        TPWrite "by taskid " \Bool:=(GetTSPStatus(T_ROB1Id) = TSP_STATUS_ACT);
        SetDO doLamp, 1;
        TPWrite "lamp " \Num:=DOutput(doLamp);
    ENDPROC
ENDMODULE
