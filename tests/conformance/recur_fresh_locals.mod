MODULE recur_fresh_locals
    ! In a recursive call chain each routine instance gets its own routine
    ! data (manual 1.2.2, storage class).
    PROC dive(num depth)
        VAR num mine;
        VAR num calls;
        mine := depth * 10;
        calls := calls + 1;
        IF depth < 3 dive depth + 1;
        TPWrite "depth " + ValToStr(depth) + " mine " + ValToStr(mine) + " calls " + ValToStr(calls);
    ENDPROC

    PROC main()
        dive 1;
    ENDPROC
ENDMODULE
