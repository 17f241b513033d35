MODULE goto_loop
    ! A backward GOTO builds a loop (manual 1.5: jump to a label in the
    ! same routine).
    PROC main()
        VAR num i := 0;
        again:
        i := i + 1;
        TPWrite "i=" \Num:=i;
        IF i < 3 GOTO again;
        TPWrite "done";
    ENDPROC
ENDMODULE
