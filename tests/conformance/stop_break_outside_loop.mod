MODULE stop_break_outside_loop
    ! Outside a loop Break keeps its debugging meaning (manual 1.5, "终止程序执行过程"):
    ! execution stops there, as Stop does (exit status 0).
    PROC main()
        TPWrite "before";
        Break;
        TPWrite "after";
    ENDPROC
ENDMODULE
