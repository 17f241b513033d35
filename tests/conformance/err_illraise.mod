MODULE err_illraise
    ! RAISE with a number outside 1..90 gives ERR_ILLRAISE (semantics 1.1);
    ! unhandled here. (A variable is used: a constant 91 would be reported
    ! by rapid check.)
    PROC main()
        VAR num e := 91;
        TPWrite "raising";
        RAISE e;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
