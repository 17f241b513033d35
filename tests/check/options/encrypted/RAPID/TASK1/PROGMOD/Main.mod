MODULE Main
    ! TuneInit and tune_gain come from TuneLib.mod, a module shipped encrypted.
    PROC main()
        TuneInit;
        TPWrite "gain: " \Num:=tune_gain;
    ENDPROC
ENDMODULE
