MODULE opt_cond_func
    ! Conditional argument in a function call (manual 1.3.4).
    FUNC num scale(num x \num factor)
        IF Present(factor) RETURN x * factor;
        RETURN x;
    ENDFUNC

    PROC caller(\num f)
        TPWrite "r=" \Num:=scale(3 \factor?f);
    ENDPROC

    PROC main()
        caller \f:=4;
        caller;
        TPWrite "d=" \Num:=scale(5 \factor:=0.5);
    ENDPROC
ENDMODULE
