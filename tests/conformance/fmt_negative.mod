MODULE fmt_negative
    ! FORMAT-DEPENDENT. Negative values keep their sign in every form.
    PROC main()
        TPWrite "a=" \Num:=-2 / 3;
        TPWrite "b=" \Num:=-0.000123;
        TPWrite "c=" \Num:=-0.00001;
        TPWrite "d=" \Num:=-9E9;
        TPWrite "e=" \Num:=-100 / 7;
    ENDPROC
ENDMODULE
