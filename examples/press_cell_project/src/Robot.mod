MODULE Robot
    ! T_ROB1: takes each part from the feeder (diPartPresent), loads the press and
    ! unloads it. It meets T_PRESS at two sync points per part and counts the parts
    ! in partsDone, a persistent every task shares.
    PERS num partsDone := 0;
    PERS tasks cellTasks{2} := [["T_ROB1"], ["T_PRESS"]];
    VAR syncident syncLoaded;
    VAR syncident syncPressed;
    VAR syncident syncEnd;

    PROC main()
        partsDone := 0;
        FOR i FROM 1 TO 3 DO
            WaitDI diPartPresent, 1;
            TPWrite "robot: picking part " \Num:=i;
            ! Tell the feeder the part is taken.
            PulseDO \PLength:=0.2, doPartTaken;
            ! Gripping the part and carrying it into the press.
            WaitTime 0.4;
            WaitSyncTask syncLoaded, cellTasks;
            WaitSyncTask syncPressed, cellTasks;
            ! Unloading the pressed part.
            WaitTime 0.35;
            partsDone := partsDone + 1;
            TPWrite "robot: part " + NumToStr(i, 0) + " done";
        ENDFOR
        WaitSyncTask syncEnd, cellTasks;
    ENDPROC
ENDMODULE
