MODULE recover_raise_from_func
    ! RAISE inside a FUNC without handler: the caller's handler gets the
    ! user number and may RETURN from the caller.
    FUNC num checked(num v)
        IF v > 100 RAISE 9;
        RETURN v;
    ENDFUNC

    PROC use(num v)
        TPWrite "value " \Num:=checked(v);
    ERROR
        IF ERRNO = 9 THEN
            TPWrite "too big " \Num:=v;
            RETURN;
        ENDIF
    ENDPROC

    PROC main()
        use 50;
        use 500;
        use 100;
    ENDPROC
ENDMODULE
