MODULE recover_retry_limit_ok
    ! Exactly 4 RETRYs are allowed (manual 1.12: up to four error
    ! recoveries; semantics 1.1: default maximum 4): the statement fails four
    ! times and succeeds on its fifth execution.
    PROC main()
        VAR num attempts := 0;
        VAR num d := 0;
        VAR num r;
        r := 12 / d;
        TPWrite "r=" \Num:=r;
    ERROR
        attempts := attempts + 1;
        TPWrite "attempt " \Num:=attempts;
        IF attempts = 4 d := 6;
        RETRY;
    ENDPROC
ENDMODULE
