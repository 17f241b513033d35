MODULE arr_bubble_sort
    ! Bubble sort; swap takes two array elements as VAR arguments.
    PROC swap(VAR num x, VAR num y)
        VAR num t;
        t := x;
        x := y;
        y := t;
    ENDPROC

    PROC main()
        VAR num a{6} := [5, 3, 8, 1, 9, 2];
        VAR string s := "";
        FOR i FROM 1 TO 5 DO
            FOR j FROM 1 TO 6 - i DO
                IF a{j} > a{j + 1} swap a{j}, a{j + 1};
            ENDFOR
        ENDFOR
        FOR i FROM 1 TO 6 DO
            IF i > 1 s := s + " ";
            s := s + ValToStr(a{i});
        ENDFOR
        TPWrite s;
    ENDPROC
ENDMODULE
