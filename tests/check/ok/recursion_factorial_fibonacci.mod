MODULE recursion_factorial_fibonacci
    ! Recursive helper functions used by the layout planner:
    ! factorial, Fibonacci, greatest common divisor, integer power,
    ! recursive binary search and the Hanoi move count.

    VAR num nCalls:=0;
    VAR num nSortedSlots{10}:=[3,8,15,21,34,55,89,144,233,377];
    VAR num nHanoiMoves:=0;

    PROC main()
        TPWrite "7! = "\Num:=factorial(7);
        TPWrite "fib(15) = "\Num:=fibonacci(15);
        TPWrite "fib_fast(30) = "\Num:=fib_iter(30);
        TPWrite "gcd(1071,462) = "\Num:=gcd(1071,462);
        TPWrite "3^7 = "\Num:=int_pow(3,7);
        TPWrite "slot of 89: "\Num:=bin_search(nSortedSlots,89,1,Dim(nSortedSlots,1));
        nHanoiMoves:=0;
        hanoi 5,1,3,2;
        TPWrite "Hanoi moves: "\Num:=nHanoiMoves;
        TPWrite "Recursive calls: "\Num:=nCalls;
    ENDPROC

    FUNC num factorial(num n)
        nCalls:=nCalls+1;
        IF n<=1 RETURN 1;
        RETURN n*factorial(n-1);
    ENDFUNC

    FUNC num fibonacci(num n)
        nCalls:=nCalls+1;
        IF n<2 THEN
            RETURN n;
        ENDIF
        RETURN fibonacci(n-1)+fibonacci(n-2);
    ENDFUNC

    ! Iterative version for comparison
    FUNC num fib_iter(num n)
        VAR num a:=0;
        VAR num b:=1;
        VAR num t;
        FOR i FROM 1 TO n DO
            t:=a+b;
            a:=b;
            b:=t;
        ENDFOR
        RETURN a;
    ENDFUNC

    FUNC num gcd(num a,num b)
        nCalls:=nCalls+1;
        IF b=0 RETURN a;
        RETURN gcd(b,a MOD b);
    ENDFUNC

    ! Fast exponentiation by squaring, exp must be a natural number
    FUNC num int_pow(num base_val,num exponent)
        VAR num half;
        nCalls:=nCalls+1;
        IF exponent=0 RETURN 1;
        half:=int_pow(base_val,exponent DIV 2);
        IF exponent MOD 2=0 THEN
            RETURN half*half;
        ELSE
            RETURN base_val*half*half;
        ENDIF
    ENDFUNC

    FUNC num bin_search(num arr{*},num key,num lo,num hi)
        VAR num mid;
        nCalls:=nCalls+1;
        IF lo>hi RETURN -1;
        mid:=(lo+hi) DIV 2;
        IF arr{mid}=key THEN
            RETURN mid;
        ELSEIF arr{mid}<key THEN
            RETURN bin_search(arr,key,mid+1,hi);
        ELSE
            RETURN bin_search(arr,key,lo,mid-1);
        ENDIF
    ENDFUNC

    ! Recursive procedure: move n discs from peg 'from' to peg 'to'
    PROC hanoi(num n,num from_peg,num to_peg,num via_peg)
        IF n=0 RETURN;
        hanoi n-1,from_peg,via_peg,to_peg;
        nHanoiMoves:=nHanoiMoves+1;
        hanoi n-1,via_peg,to_peg,from_peg;
    ENDPROC

ENDMODULE
