MODULE optional_switch_parameters
    ! Parameter passing in a small motion/utility library:
    ! optional parameters and Present, switches, mutually exclusive
    ! alternatives, conditional arguments (\Arg?Param), open array
    ! parameters with Dim, and INOUT / VAR / PERS access modes.

    PERS tooldata tDrill:=[TRUE,[[0,0,245],[1,0,0,0]],[5.5,[0,0,100],[1,0,0,0],0.04,0.04,0.02]];
    PERS wobjdata wobjPlate:=[FALSE,TRUE,"",[[1000,-250,300],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS num nHolesDrilled:=0;
    CONST robtarget pHoleRef:=[[50,50,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    VAR signaldi di_spindle_ready;
    VAR num nDepths{5}:=[12,12,8,20,15];
    VAR num nLastDepth:=0;

    PROC main()
        VAR num nTotal;
        VAR bool bTimedOut;
        AliasIO "diSpindleReady",di_spindle_ready;
        ! Optional arguments left out, given, and given by name
        drill_hole pHoleRef,10;
        drill_hole Offs(pHoleRef,40,0,0),10\Peck:=3;
        drill_hole Offs(pHoleRef,80,0,0),Depth:=12\Peck:=4\Slow;
        ! Mutually exclusive alternatives
        move_safe pHoleRef\Fast;
        move_safe pHoleRef\Speed:=v200;
        move_safe pHoleRef\Time:=2.5;
        ! Conditional arguments are passed on only when present
        wait_ready\MaxTime:=5\TimeFlag:=bTimedOut;
        wait_ready;
        ! Open array parameters
        nTotal:=sum_of(nDepths);
        scale_all nDepths,1.1;
        TPWrite "Total depth "\Num:=nTotal;
        bump_counter nHolesDrilled;
        record_depth nLastDepth,nDepths{4};
    ENDPROC

    ! Depth is required, Peck and Slow are optional
    PROC drill_hole(robtarget hole,num Depth\num Peck\switch Slow)
        VAR num nStep;
        VAR speeddata vFeed:=v20;
        IF Present(Slow) vFeed:=v5;
        IF Present(Peck) THEN
            nStep:=Peck;
        ELSE
            nStep:=Depth;
        ENDIF
        MoveJ Offs(hole,0,0,50),v1000,z10,tDrill\WObj:=wobjPlate;
        FOR d FROM nStep TO Depth STEP nStep DO
            MoveL Offs(hole,0,0,-d),vFeed,fine,tDrill\WObj:=wobjPlate;
            MoveL Offs(hole,0,0,2),v500,z1,tDrill\WObj:=wobjPlate;
        ENDFOR
        MoveL Offs(hole,0,0,50),v1000,z10,tDrill\WObj:=wobjPlate;
    ENDPROC

    ! Exactly one of \Fast, \Speed or \Time may be given (or none)
    PROC move_safe(robtarget target\switch Fast|speeddata Speed|num Time)
        IF Present(Fast) THEN
            MoveJ Offs(target,0,0,200),v2000,z50,tDrill\WObj:=wobjPlate;
        ELSEIF Present(Speed) THEN
            MoveJ Offs(target,0,0,200),Speed,z50,tDrill\WObj:=wobjPlate;
        ELSEIF Present(Time) THEN
            MoveJ Offs(target,0,0,200),v1000\T:=Time,z50,tDrill\WObj:=wobjPlate;
        ELSE
            MoveJ Offs(target,0,0,200),v500,z50,tDrill\WObj:=wobjPlate;
        ENDIF
    ENDPROC

    ! Mutually exclusive numeric alternatives, the formal example form
    FUNC num feed_rate(\num PerRev|num PerMin)
        IF Present(PerRev) RETURN PerRev*1500;
        IF Present(PerMin) RETURN PerMin;
        RETURN 300;
    ENDFUNC

    PROC wait_ready(\num MaxTime\VAR bool TimeFlag)
        ! \MaxTime and \TimeFlag are only passed to WaitDI if present here
        WaitDI di_spindle_ready,1\MaxTime?MaxTime\TimeFlag?TimeFlag;
    ENDPROC

    FUNC num sum_of(num values{*})
        VAR num nSum:=0;
        FOR i FROM 1 TO Dim(values,1) DO
            nSum:=nSum+values{i};
        ENDFOR
        RETURN nSum;
    ENDFUNC

    PROC scale_all(INOUT num values{*},num factor)
        FOR i FROM 1 TO Dim(values,1) DO
            values{i}:=values{i}*factor;
        ENDFOR
    ENDPROC

    PROC bump_counter(PERS num counter)
        counter:=counter+1;
    ENDPROC

    PROC record_depth(VAR num target,num depth)
        target:=depth;
        TPWrite "Feed: "\Num:=feed_rate(\PerRev:=0.12);
        TPWrite "Feed: "\Num:=feed_rate(\PerMin:=250);
    ENDPROC

ENDMODULE
