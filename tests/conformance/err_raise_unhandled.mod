MODULE err_raise_unhandled
    ! A user error that no routine handles stops execution (exit 1). How the
    ! system handler names a user number is not fixed, so stderr is not checked.
    PROC deep()
        TPWrite "deep";
        RAISE 42;
    ENDPROC

    PROC main()
        deep;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
