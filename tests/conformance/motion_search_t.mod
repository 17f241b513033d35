MODULE motion_search_t
    ! SearchL \T: the search move takes T = 2 s (at v100 alone it would take
    ! 100/100 + 100/10000 = 1.01 s); nothing is found, so ERR_WHLSEARCH comes when the
    ! robot stands at ToPoint: 2 s + 0.05 s settle.
    PERS bool hitFlag := FALSE;
    VAR robtarget hit;
    VAR clock c;
    CONST robtarget p0 := [[300,-50,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        ConfL \Off;
        MoveL p0, v500, fine, tool0;
        ClkStart c;
        SearchL hitFlag, hit, Offs(p0, 0, 100, 0), v100 \T:=2, tool0;
        TPWrite "no error";
    ERROR
        IF ERRNO = ERR_WHLSEARCH THEN
            TPWrite "ERR_WHLSEARCH after " \Num:=ClkRead(c);
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
