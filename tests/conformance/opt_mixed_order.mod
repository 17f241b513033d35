MODULE opt_mixed_order
    ! A required parameter after an optional one (manual 1.1.5 syntax:
    ! parameter lists mix both kinds).
    PROC p(num a \num b, num c)
        VAR num total;
        total := a + c;
        IF Present(b) total := total + b;
        TPWrite "total=" \Num:=total;
    ENDPROC

    PROC main()
        p 1, 3;
        p 1 \b:=20, 3;
    ENDPROC
ENDMODULE
