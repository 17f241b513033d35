MODULE test_case_goto_labels
    ! Operator menu and part sorting for a test bench.
    ! TEST with several values per CASE and DEFAULT, compact IF,
    ! GOTO with labels (also jumping backwards to build a loop).

    CONST num GRADE_A:=1;
    CONST num GRADE_B:=2;
    CONST num GRADE_SCRAP:=9;

    VAR num nGradeCount{3}:=[0,0,0];
    VAR num nAnswer:=0;
    VAR num nTries:=0;
    VAR string sMode:="AUTO";
    VAR num nMeasured:=0;

    PROC main()
        menu_start:
        TPReadFK nAnswer,"Select function","Measure","Sort","Stats",stEmpty,"Exit";
        TEST nAnswer
        CASE 1:
            measure_part;
        CASE 2:
            sort_part classify(nMeasured);
        CASE 3:
            show_stats;
        CASE 5:
            GOTO menu_end;
        DEFAULT:
            TPWrite "Key not used";
        ENDTEST
        GOTO menu_start;
        menu_end:
        TPWrite "Leaving menu";
    ENDPROC

    PROC measure_part()
        nTries:=0;
        again:
        nTries:=nTries+1;
        TPReadNum nMeasured,"Enter measured length [mm]";
        IF nMeasured<=0 AND nTries<3 GOTO again;
        IF nMeasured<=0 nMeasured:=0;
    ENDPROC

    FUNC num classify(num length)
        VAR num nDev;
        nDev:=Abs(length-250);
        IF nDev<=0.05 THEN
            RETURN GRADE_A;
        ELSEIF nDev<=0.2 THEN
            RETURN GRADE_B;
        ELSE
            RETURN GRADE_SCRAP;
        ENDIF
    ENDFUNC

    PROC sort_part(num grade)
        TEST grade
        CASE GRADE_A:
            nGradeCount{1}:=nGradeCount{1}+1;
        CASE GRADE_B,3,4:
            nGradeCount{2}:=nGradeCount{2}+1;
        CASE GRADE_SCRAP,0:
            nGradeCount{3}:=nGradeCount{3}+1;
            IF sMode="AUTO" TPWrite "Part scrapped";
        DEFAULT:
            TPWrite "Unexpected grade "\Num:=grade;
        ENDTEST
    ENDPROC

    PROC show_stats()
        VAR num nTotal;
        nTotal:=nGradeCount{1}+nGradeCount{2}+nGradeCount{3};
        IF nTotal=0 GOTO no_parts;
        TPWrite "A: "\Num:=nGradeCount{1};
        TPWrite "B: "\Num:=nGradeCount{2};
        TPWrite "Scrap: "\Num:=nGradeCount{3};
        TPWrite "Yield %: "\Num:=Round(100*(nGradeCount{1}+nGradeCount{2})/nTotal\Dec:=1);
        RETURN;
        no_parts:
        TPWrite "No parts measured yet";
    ENDPROC

    ! Mode switch with strings in TEST
    PROC set_mode(string mode)
        TEST mode
        CASE "AUTO","AUTOMATIC":
            sMode:="AUTO";
        CASE "MAN","MANUAL","SETUP":
            sMode:="MAN";
        DEFAULT:
            sMode:="AUTO";
        ENDTEST
    ENDPROC

ENDMODULE
