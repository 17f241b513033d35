MODULE while_nested
    ! Nested WHILE loops: count pairs (i, j) with i < j <= 4.
    PROC main()
        VAR num i := 1;
        VAR num j;
        VAR num pairs := 0;
        WHILE i <= 4 DO
            j := i + 1;
            WHILE j <= 4 DO
                pairs := pairs + 1;
                j := j + 1;
            ENDWHILE
            i := i + 1;
        ENDWHILE
        TPWrite "pairs=" \Num:=pairs;
    ENDPROC
ENDMODULE
