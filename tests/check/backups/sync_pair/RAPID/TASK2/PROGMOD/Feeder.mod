MODULE Feeder
    ! The feeder task: every half second a part, announced through the shared
    ! persistent lastPart.
    PERS num partsMade := 0;
    PERS string lastPart := "";
    PERS tasks cellTasks{2} := [["T_ROB1"], ["T_FEEDER"]];
    VAR syncident syncStart;
    VAR syncident syncPart;
    VAR syncident syncEnd;

    PROC feeder_main()
        WaitSyncTask syncStart, cellTasks;
        FOR i FROM 1 TO 3 DO
            SetDO doFeederBusy, 1;
            WaitTime 0.5;
            lastPart := "part" + NumToStr(i, 0);
            SetDO doFeederBusy, 0;
            WaitSyncTask syncPart, cellTasks;
        ENDFOR
        WaitSyncTask syncEnd, cellTasks;
        ! The robot task counted every part in the shared partsMade.
        WaitTime 0.1;
        TPWrite "feeder sees " \Num:=partsMade;
    ENDPROC
ENDMODULE
