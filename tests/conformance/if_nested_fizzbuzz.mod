MODULE if_nested_fizzbuzz
    ! ELSEIF chain inside a FOR loop.
    PROC main()
        FOR i FROM 1 TO 15 DO
            IF i MOD 15 = 0 THEN
                TPWrite "FizzBuzz";
            ELSEIF i MOD 3 = 0 THEN
                TPWrite "Fizz";
            ELSEIF i MOD 5 = 0 THEN
                TPWrite "Buzz";
            ELSE
                TPWrite "" \Num:=i;
            ENDIF
        ENDFOR
    ENDPROC
ENDMODULE
