MODULE pers_param
    ! A PERS parameter refers to the caller's whole persistent (manual 1.1.5).
    PERS num total := 1;
    PERS num other := 100;

    PROC addTo(PERS num target, num v)
        target := target + v;
    ENDPROC

    PROC main()
        addTo total, 5;
        addTo total, 7;
        addTo other, -1;
        TPWrite "total=" \Num:=total;
        TPWrite "other=" \Num:=other;
    ENDPROC
ENDMODULE
