MODULE loop_break_continue
    ! RobotWare 6.15 (manual 1.5, "程序范围内的程序控制"): Break ends the innermost
    ! enclosing loop (FOR, WHILE), Continue skips the rest of the loop body and starts
    ! the next iteration (FOR: the next value of the loop variable; WHILE: the
    ! condition). TEST is not a loop: Break in a CASE ends the loop around it.
    PROC main()
        VAR num s := 0;
        VAR num k := 0;
        VAR num n := 0;
        FOR i FROM 1 TO 10 DO
            IF i = 3 Continue;
            IF i > 5 Break;
            s := s + i;
        ENDFOR
        TPWrite "for s=" \Num:=s;
        WHILE TRUE DO
            k := k + 1;
            IF k MOD 2 = 0 Continue;
            IF k > 7 Break;
            TPWrite "odd " \Num:=k;
        ENDWHILE
        TPWrite "k=" \Num:=k;
        FOR i FROM 1 TO 3 DO
            FOR j FROM 1 TO 3 DO
                IF j = 2 Break;
                TPWrite "i,j=" + NumToStr(i, 0) + "," + NumToStr(j, 0);
            ENDFOR
        ENDFOR
        FOR i FROM 1 TO 5 DO
            TEST i
            CASE 4:
                Break;
            DEFAULT:
                n := n + 1;
            ENDTEST
        ENDFOR
        TPWrite "n=" \Num:=n;
    ENDPROC
ENDMODULE
