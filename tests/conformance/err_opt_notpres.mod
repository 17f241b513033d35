MODULE err_opt_notpres
    ! ERR_NOTPRES with no handler stops execution.
    FUNC num twice(\num v)
        RETURN v * 2;
    ENDFUNC

    PROC main()
        TPWrite "r=" \Num:=twice(\v:=4);
        TPWrite "r=" \Num:=twice();
        TPWrite "not reached";
    ENDPROC
ENDMODULE
