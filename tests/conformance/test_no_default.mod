MODULE test_no_default
    ! Without DEFAULT, a value that matches no CASE runs nothing.
    PROC main()
        VAR num v := 9;
        TEST v
        CASE 1:
            TPWrite "one";
        CASE 2:
            TPWrite "two";
        ENDTEST
        TPWrite "after";
        v := 2;
        TEST v
        CASE 1:
            TPWrite "one";
        CASE 2:
            TPWrite "two";
        ENDTEST
    ENDPROC
ENDMODULE
