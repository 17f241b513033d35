MODULE test_first_match
    ! The first matching CASE runs, with no fall-through (semantics 5, TEST).
    PROC pick(num v)
        TEST v
        CASE 1, 2:
            TPWrite "first";
        CASE 2, 3:
            TPWrite "second";
        DEFAULT:
            TPWrite "default";
        ENDTEST
    ENDPROC

    PROC main()
        pick 2;
        pick 3;
        pick 1;
        pick 4;
    ENDPROC
ENDMODULE
