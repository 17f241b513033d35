MODULE recur_fibonacci
    ! Doubly recursive Fibonacci.
    FUNC num fib(num n)
        IF n <= 2 RETURN 1;
        RETURN fib(n - 1) + fib(n - 2);
    ENDFUNC

    PROC main()
        VAR string s := "";
        FOR i FROM 1 TO 10 DO
            IF i > 1 s := s + " ";
            s := s + ValToStr(fib(i));
        ENDFOR
        TPWrite s;
        TPWrite "fib15=" \Num:=fib(15);
    ENDPROC
ENDMODULE
