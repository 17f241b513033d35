MODULE trig_dnum
    ! The ...Dnum trigonometric functions work in degrees and return dnum, with double
    ! precision: sin 30° = 0.5, cos 60° = 0.5, tan 45° = 1, and the inverses give the
    ! angles back. Each is checked against the exact value within 1E-12.
    FUNC bool near(dnum x, dnum expected)
        RETURN Abs(x - expected) < 0.000000000001;
    ENDFUNC

    PROC main()
        TPWrite "sin " \Bool:=near(SinDnum(30), 0.5);
        TPWrite "cos " \Bool:=near(CosDnum(60), 0.5);
        TPWrite "tan " \Bool:=near(TanDnum(45), 1);
        TPWrite "asin " \Bool:=near(ASinDnum(0.5), 30);
        TPWrite "acos " \Bool:=near(ACosDnum(-1), 180);
        TPWrite "atan " \Bool:=near(ATanDnum(1), 45);
        TPWrite "atan2 " \Bool:=near(ATan2Dnum(1, -1), 135);
        TPWrite "finer than num " \Bool:=Abs(SinDnum(1) - 0.0174524064372835) < 0.000000000001;
        TPWrite "asin out of range";
        TPWrite "" \Dnum:=ASinDnum(2);
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "ERR_ARGVALERR";
        RETURN;
    ENDPROC
ENDMODULE
