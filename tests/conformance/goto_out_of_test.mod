MODULE goto_out_of_test
    ! GOTO from inside a TEST case to a label after it.
    PROC main()
        VAR num v := 2;
        TEST v
        CASE 1:
            TPWrite "one";
        CASE 2:
            TPWrite "two";
            GOTO done;
        ENDTEST
        TPWrite "skipped";
        done:
        TPWrite "done";
    ENDPROC
ENDMODULE
