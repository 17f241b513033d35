MODULE recover_retry_three
    ! Three failures, three RETRYs, then success: within the limit of 4
    ! retries (manual 1.12).
    PROC main()
        VAR num attempts := 0;
        VAR num d := 0;
        VAR num r;
        r := 12 / d;
        TPWrite "r=" \Num:=r;
    ERROR
        attempts := attempts + 1;
        TPWrite "attempt " \Num:=attempts;
        IF attempts = 3 d := 6;
        RETRY;
    ENDPROC
ENDMODULE
