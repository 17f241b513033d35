MODULE recur_binary_search
    ! Recursive binary search on an open array parameter.
    FUNC num find(num a{*}, num key, num lo, num hi)
        VAR num mid;
        IF lo > hi RETURN 0;
        mid := (lo + hi) DIV 2;
        IF a{mid} = key RETURN mid;
        IF a{mid} < key RETURN find(a, key, mid + 1, hi);
        RETURN find(a, key, lo, mid - 1);
    ENDFUNC

    PROC main()
        VAR num data{10} := [2, 5, 8, 12, 16, 23, 38, 56, 72, 91];
        TPWrite "23 at " \Num:=find(data, 23, 1, 10);
        TPWrite "2 at " \Num:=find(data, 2, 1, 10);
        TPWrite "91 at " \Num:=find(data, 91, 1, 10);
        TPWrite "7 at " \Num:=find(data, 7, 1, 10);
    ENDPROC
ENDMODULE
