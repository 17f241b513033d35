MODULE param_pers_to_inout_chain
    ! A PERS passed on through PERS and INOUT parameters still refers to the
    ! same persistent.
    PERS num level := 1;

    PROC inner(INOUT num x)
        x := x * 10;
    ENDPROC

    PROC outer(PERS num p)
        p := p + 1;
        inner p;
    ENDPROC

    PROC main()
        outer level;
        TPWrite "level=" \Num:=level;
        outer level;
        TPWrite "level=" \Num:=level;
    ENDPROC
ENDMODULE
