MODULE Press
    ! T_PRESS: closes the press for 1.1 s once the robot has loaded it.
    PERS num partsDone := 0;
    PERS tasks cellTasks{2} := [["T_ROB1"], ["T_PRESS"]];
    VAR syncident syncLoaded;
    VAR syncident syncPressed;
    VAR syncident syncEnd;

    PROC press_main()
        FOR i FROM 1 TO 3 DO
            WaitSyncTask syncLoaded, cellTasks;
            SetDO doPressClose, 1;
            TPWrite "press: pressing part " \Num:=i;
            WaitTime 1.1;
            SetDO doPressClose, 0;
            WaitSyncTask syncPressed, cellTasks;
        ENDFOR
        WaitSyncTask syncEnd, cellTasks;
        TPWrite "press: " + NumToStr(partsDone, 0) + " parts pressed";
    ENDPROC
ENDMODULE
