MODULE recur_hanoi
    ! Towers of Hanoi with 3 discs: 7 moves.
    VAR num moves := 0;

    PROC hanoi(num n, string src, string dst, string via)
        IF n = 0 RETURN;
        hanoi n - 1, src, via, dst;
        moves := moves + 1;
        TPWrite "move " + ValToStr(n) + " " + src + "->" + dst;
        hanoi n - 1, via, dst, src;
    ENDPROC

    PROC main()
        hanoi 3, "A", "C", "B";
        TPWrite "moves=" \Num:=moves;
    ENDPROC
ENDMODULE
