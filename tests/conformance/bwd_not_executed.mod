MODULE bwd_not_executed
    ! A BACKWARD handler only runs when the procedure is executed backwards
    ! step by step (manual 1.21); a normal forward run never executes it.
    PROC moveTo()
        TPWrite "forward 1";
        TPWrite "forward 2";
    BACKWARD
        TPWrite "backward 2";
        TPWrite "backward 1";
    ENDPROC

    PROC main()
        moveTo;
        moveTo;
        TPWrite "done";
    ENDPROC
ENDMODULE
