MODULE undo_order_chain
    ! UNDO handlers run bottom-up along the call chain (manual 1.13): the one
    ! nearest the end of the chain first, main's last; routines without
    ! UNDO are skipped.
    PROC lvC()
        TPWrite "C";
        EXIT;
    UNDO
        TPWrite "undo C";
    ENDPROC

    PROC lvB()
        TPWrite "B";
        lvC;
    ENDPROC

    PROC lvA()
        TPWrite "A";
        lvB;
    UNDO
        TPWrite "undo A";
    ENDPROC

    PROC main()
        TPWrite "main";
        lvA;
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
