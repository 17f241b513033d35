MODULE opt_switch
    ! A switch has no value; Present tells whether it was given (manual 1.1.5).
    PROC report(num v \switch verbose)
        IF Present(verbose) THEN
            TPWrite "the value is " \Num:=v;
        ELSE
            TPWrite "" \Num:=v;
        ENDIF
    ENDPROC

    FUNC num scaled(num v \switch double)
        IF Present(double) RETURN v * 2;
        RETURN v;
    ENDFUNC

    PROC main()
        report 4;
        report 5 \verbose;
        TPWrite "s=" \Num:=scaled(3);
        TPWrite "s=" \Num:=scaled(3 \double);
    ENDPROC
ENDMODULE
