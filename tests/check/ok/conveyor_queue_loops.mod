MODULE conveyor_queue_loops
    ! Part queue of an accumulating conveyor with 8 places.
    ! Exercises WHILE, FOR with positive and negative STEP,
    ! IF/ELSEIF/ELSE chains and compact IF statements.

    CONST num QUEUE_LEN:=8;
    VAR num nQueue{8}:=[0,0,0,0,0,0,0,0];
    VAR num nHead:=0;
    VAR num nShifted:=0;
    VAR bool bJam:=FALSE;

    VAR signalgi gi_sensors;
    VAR signaldo do_stopper;

    PROC main()
        VAR num nPart;
        bind_signals;
        nPart:=1000;
        WHILE nPart<1010 DO
            enqueue nPart;
            nPart:=nPart+1;
            IF nHead>=QUEUE_LEN-2 THEN
                release_first;
            ELSEIF nHead>=QUEUE_LEN/2 THEN
                TPWrite "Queue half full";
            ELSE
                WaitTime 0.1;
            ENDIF
        ENDWHILE
        drain_queue;
    ENDPROC

    PROC bind_signals()
        ! The 8 place sensors are mapped as one group input, bit 1 = place 1
        AliasIO "giConvSensors",gi_sensors;
        AliasIO "doStopper",do_stopper;
    ENDPROC

    PROC enqueue(num part_id)
        IF nHead>=QUEUE_LEN THEN
            bJam:=TRUE;
            TPWrite "Queue full, part dropped: "\Num:=part_id;
            RETURN;
        ENDIF
        nHead:=nHead+1;
        nQueue{nHead}:=part_id;
    ENDPROC

    ! Remove the first part and shift the others forward
    PROC release_first()
        IF nHead=0 RETURN;
        PulseDO\PLength:=0.4,do_stopper;
        FOR i FROM 1 TO nHead-1 DO
            nQueue{i}:=nQueue{i+1};
        ENDFOR
        nQueue{nHead}:=0;
        nHead:=nHead-1;
        Incr nShifted;
    ENDPROC

    ! Empty the queue from the back (counting down)
    PROC drain_queue()
        FOR i FROM nHead TO 1 STEP -1 DO
            TPWrite "Draining part "\Num:=nQueue{i};
            nQueue{i}:=0;
        ENDFOR
        nHead:=0;
        ! Check every second place sensor: 8, 6, 4, 2
        FOR s FROM 8 TO 2 STEP -2 DO
            IF BitCheck(GInput(gi_sensors),s) TPWrite "Sensor still occupied: "\Num:=s;
        ENDFOR
    ENDPROC

    ! Count occupied sensors, stop counting at the first free place
    FUNC num occupied_from_start()
        VAR num n:=0;
        VAR bool bFree:=FALSE;
        VAR byte nBits;
        nBits:=GInput(gi_sensors);
        WHILE (NOT bFree) AND n<QUEUE_LEN DO
            IF BitCheck(nBits,n+1) THEN
                n:=n+1;
            ELSE
                bFree:=TRUE;
            ENDIF
        ENDWHILE
        RETURN n;
    ENDFUNC

    FUNC string queue_state()
        VAR num nOcc;
        nOcc:=occupied_from_start();
        IF bJam THEN
            RETURN "JAM";
        ELSEIF nOcc=0 THEN
            RETURN "EMPTY";
        ELSEIF nOcc<QUEUE_LEN THEN
            RETURN "PARTIAL";
        ENDIF
        RETURN "FULL";
    ENDFUNC

ENDMODULE
