MODULE MainModule
    ! Weld cell main program: welds all seams of the fixture.

    PROC main()
        weld_init;
        log_event "Cycle start";
        MoveAbsJ jWeldHome,v1000,z50,tTorch;
        FOR i FROM 1 TO Dim(SEAMS,1) DO
            weld_seam pSeamStart{i},SEAMS{i};
        ENDFOR
        MoveAbsJ jWeldHome,v1000,fine,tTorch;
        log_event "Cycle end, seams total "+NumToStr(nSeamsWelded,0);
    ENDPROC

ENDMODULE
