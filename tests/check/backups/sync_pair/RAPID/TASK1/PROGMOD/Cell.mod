MODULE Cell
    ! The robot task: takes each part the feeder task announces in the shared
    ! persistent lastPart, meeting it at the sync points of WaitSyncTask.
    PERS num partsMade := 0;
    PERS string lastPart := "";
    PERS tasks cellTasks{2} := [["T_ROB1"], ["T_FEEDER"]];
    VAR syncident syncStart;
    VAR syncident syncPart;
    VAR syncident syncEnd;

    PROC main()
        partsMade := 0;
        WaitSyncTask syncStart, cellTasks;
        FOR i FROM 1 TO 3 DO
            ! The feeder has put part i into lastPart before it arrives here.
            WaitSyncTask syncPart, cellTasks;
            TPWrite "robot took " + lastPart;
            partsMade := partsMade + 1;
        ENDFOR
        WaitSyncTask syncEnd, cellTasks;
        TPWrite "robot made " \Num:=partsMade;
    ENDPROC
ENDMODULE
