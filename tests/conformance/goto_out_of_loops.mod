MODULE goto_out_of_loops
    ! GOTO may leave FOR and WHILE loops (jumping into them from outside is
    ! what is forbidden, semantics 5); it is the way to end a loop early.
    PROC main()
        VAR num found := 0;
        VAR num n := 0;
        FOR i FROM 1 TO 10 DO
            IF i * i > 20 THEN
                found := i;
                GOTO out1;
            ENDIF
        ENDFOR
        TPWrite "not found";
        out1:
        TPWrite "found=" \Num:=found;
        WHILE TRUE DO
            n := n + 1;
            IF n = 4 GOTO out2;
        ENDWHILE
        out2:
        TPWrite "n=" \Num:=n;
    ENDPROC
ENDMODULE
