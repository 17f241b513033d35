MODULE test_basic
    ! TEST with several values per CASE and a DEFAULT (manual 1.5, semantics 5).
    PROC describe(num n)
        TEST n
        CASE 1, 2, 3:
            TPWrite "small " \Num:=n;
        CASE 4:
            TPWrite "four";
        CASE 5, 6:
            TPWrite "five or six";
        DEFAULT:
            TPWrite "other " \Num:=n;
        ENDTEST
    ENDPROC

    PROC main()
        FOR i FROM 1 TO 7 DO
            describe i;
        ENDFOR
    ENDPROC
ENDMODULE
