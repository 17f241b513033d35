MODULE records_aliases_local_data
    ! Part tracking for an assembly line.
    ! Shows user record types (also nested and in arrays), ALIAS types,
    ! LOCAL declarations and record aggregates.

    ALIAS num station_id;
    ALIAS string serial_text;
    ALIAS bool quality_flag;
    LOCAL ALIAS num kilogram;

    RECORD part_info
        serial_text serial;
        num variant;
        num weight_kg;
        pos grip_offset;
        quality_flag passed;
    ENDRECORD

    RECORD station_result
        station_id station;
        num cycle_time;
        part_info part;
        string operator_note;
    ENDRECORD

    LOCAL RECORD limit_pair
        kilogram lower;
        kilogram upper;
    ENDRECORD

    CONST station_id STATION_PRESS:=20;
    CONST station_id STATION_TEST:=30;
    CONST part_info EMPTY_PART:=["",0,0,[0,0,0],FALSE];
    LOCAL CONST limit_pair WEIGHT_LIMITS:=[2.35,2.65];
    CONST pos EXTRA_LIFT:=[0,0,2.5];

    VAR part_info piCurrent:=["SN000000",1,2.5,[0,0,15],FALSE];
    VAR station_result srHistory{5};
    VAR num nHistoryCount:=0;
    PERS part_info piLastGood:=["SN104711",2,2.48,[0,-3,15],TRUE];
    LOCAL VAR num nRejects:=0;

    PROC main()
        VAR station_result srNow;
        piCurrent:=make_part("SN104712",2,2.51);
        piCurrent.grip_offset:=piCurrent.grip_offset+EXTRA_LIFT;
        piCurrent.passed:=weight_ok(piCurrent.weight_kg);
        srNow:=[STATION_TEST,14.2,piCurrent,"auto"];
        push_history srNow;
        IF srNow.part.passed THEN
            piLastGood:=srNow.part;
        ELSE
            nRejects:=nRejects+1;
        ENDIF
        print_history;
    ENDPROC

    FUNC part_info make_part(serial_text serial,num variant,num weight)
        VAR part_info p;
        p:=EMPTY_PART;
        p.serial:=serial;
        p.variant:=variant;
        p.weight_kg:=weight;
        p.grip_offset:=[0,0,15];
        RETURN p;
    ENDFUNC

    LOCAL FUNC quality_flag weight_ok(num weight)
        RETURN weight>=WEIGHT_LIMITS.lower AND weight<=WEIGHT_LIMITS.upper;
    ENDFUNC

    PROC push_history(station_result result)
        IF nHistoryCount<Dim(srHistory,1) THEN
            nHistoryCount:=nHistoryCount+1;
        ELSE
            ! Shift the ring, oldest entry is dropped
            FOR i FROM 1 TO Dim(srHistory,1)-1 DO
                srHistory{i}:=srHistory{i+1};
            ENDFOR
        ENDIF
        srHistory{nHistoryCount}:=result;
    ENDPROC

    LOCAL PROC print_history()
        VAR station_id st;
        FOR i FROM 1 TO nHistoryCount DO
            st:=srHistory{i}.station;
            TPWrite "St "+NumToStr(st,0)+" "+srHistory{i}.part.serial\Num:=srHistory{i}.cycle_time;
            IF srHistory{i}.station=STATION_PRESS TPWrite "  press data: "+srHistory{i}.operator_note;
        ENDFOR
        TPWrite "Rejects: "\Num:=nRejects;
    ENDPROC

ENDMODULE
