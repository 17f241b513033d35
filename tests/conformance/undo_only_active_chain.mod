MODULE undo_only_active_chain
    ! Only routines still in the call chain have their UNDO run: early()
    ! has already returned when EXIT happens.
    PROC early()
        TPWrite "early";
    UNDO
        TPWrite "undo early";
    ENDPROC

    PROC late()
        TPWrite "late";
        EXIT;
    UNDO
        TPWrite "undo late";
    ENDPROC

    PROC main()
        early;
        late;
    ENDPROC
ENDMODULE
