MODULE late_binding_dispatch
    ! Product dispatcher: the PLC sends a product number and the
    ! matching program routine is called by name (late binding).
    ! All product routines take the same parameters.

    VAR num nProduct:=0;
    VAR string sProcName{4}:=["prod_bracket","prod_hinge","prod_cover","prod_frame"];
    VAR num nCallsFailed:=0;
    VAR num nUnits:=0;

    VAR signalgi gi_product;
    VAR signaldi di_start;

    PERS tooldata tWelder:=[TRUE,[[0,0,350],[1,0,0,0]],[4,[0,0,150],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjTable:=[FALSE,TRUE,"",[[900,0,500],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];

    PROC main()
        AliasIO "giProductNo",gi_product;
        AliasIO "diCycleStart",di_start;
        WHILE TRUE DO
            WaitDI di_start,1;
            nProduct:=GInput(gi_product);
            run_product nProduct;
            run_station_sequence;
        ENDWHILE
    ENDPROC

    PROC run_product(num product)
        VAR num nLength;
        VAR num nHeight;
        nLength:=100+product*20;
        nHeight:=15;
        ! Variant 1: the routine name is built from a string expression
        % "prod_" + NumToStr(product,0) % nLength,nHeight;
        ! Variant 2: the routine name is taken from a table
        IF product>=1 AND product<=Dim(sProcName,1) THEN
            %sProcName{product}% nLength,nHeight;
        ENDIF
    ERROR
        IF ERRNO=ERR_REFUNKPRC THEN
            TPWrite "No routine for product "\Num:=product;
            nCallsFailed:=nCallsFailed+1;
            TRYNEXT;
        ELSEIF ERRNO=ERR_CALLPROC THEN
            TPWrite "Routine for product has wrong parameters";
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

    ! CallByVar calls "station_1", "station_2"... (no parameters)
    PROC run_station_sequence()
        FOR st FROM 1 TO 3 DO
            CallByVar "station_",st;
        ENDFOR
    ERROR
        IF ERRNO=ERR_REFUNKPRC THEN
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

    PROC prod_1(num length,num height)
        prod_bracket length,height;
    ENDPROC

    PROC prod_2(num length,num height)
        prod_hinge length,height;
    ENDPROC

    PROC prod_bracket(num length,num height)
        weld_line [[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],length;
        weld_line [[0,height,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],length;
    ENDPROC

    PROC prod_hinge(num length,num height)
        weld_line [[50,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],length/2;
    ENDPROC

    PROC prod_cover(num length,num height)
        weld_line [[0,0,height],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],length;
    ENDPROC

    PROC prod_frame(num length,num height)
        FOR side FROM 0 TO 3 DO
            weld_line [[side*length,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],length;
        ENDFOR
    ENDPROC

    PROC weld_line(robtarget start,num length)
        MoveJ Offs(start,0,0,50),v1000,z20,tWelder\WObj:=wobjTable;
        MoveL start,v100,fine,tWelder\WObj:=wobjTable;
        MoveL Offs(start,length,0,0),v20,fine,tWelder\WObj:=wobjTable;
        MoveL Offs(start,length,0,50),v500,z20,tWelder\WObj:=wobjTable;
        nUnits:=nUnits+1;
    ENDPROC

    PROC station_1()
        TPWrite "Station 1: clamp";
    ENDPROC

    PROC station_2()
        TPWrite "Station 2: weld";
    ENDPROC

    PROC station_3()
        TPWrite "Station 3: unclamp";
    ENDPROC

ENDMODULE
