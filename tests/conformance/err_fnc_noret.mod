MODULE err_fnc_noret
    ! A FUNC must end with RETURN (manual 1.1.5); reaching ENDFUNC raises
    ! ERR_FNCNORET (semantics 1.3). Here sign(0) falls through.
    FUNC num sign(num x)
        IF x > 0 RETURN 1;
        IF x < 0 RETURN -1;
    ENDFUNC

    PROC main()
        TPWrite "s=" \Num:=sign(5);
        TPWrite "s=" \Num:=sign(-2);
        TPWrite "s=" \Num:=sign(0);
        TPWrite "not reached";
    ENDPROC
ENDMODULE
