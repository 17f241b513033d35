MODULE late_callbyvar
    ! CallByVar calls the procedure whose name is Name followed by Number
    ! (manual 1.5, semantics 3.9).
    PROC proc1()
        TPWrite "one";
    ENDPROC

    PROC proc2()
        TPWrite "two";
    ENDPROC

    PROC proc3()
        TPWrite "three";
    ENDPROC

    PROC main()
        CallByVar "proc", 2;
        FOR i FROM 1 TO 3 DO
            CallByVar "proc", i;
        ENDFOR
    ENDPROC
ENDMODULE
