MODULE errlog_kinds
    ! ErrLog writes the event log only (the program goes on, nothing on stdout); \W and
    ! \I make warnings and information. ErrWrite shows its lines on the pendant and
    ! logs them as user event 80001 (80002 with \W, 80003 with \I).
    PROC main()
        ErrLog 4800 \W, "Low air", "Check the supply", ERRSTR_EMPTY, ERRSTR_UNUSED, ERRSTR_UNUSED;
        ErrLog 4999 \I, "Cycle done", ERRSTR_TASK, ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
        ErrLog 4850, "Jammed", ERRSTR_CONTEXT, ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
        ErrWrite \I, "Note", "Line two" \RL2:="Line three";
        TPWrite "end";
    ENDPROC
ENDMODULE
