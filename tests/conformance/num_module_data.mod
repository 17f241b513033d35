MODULE num_module_data
    ! Start-up data of manual 1.2.2: CONST and VAR may be initialised with
    ! constant expressions, PERS with literals only.
    CONST num a := 2;
    CONST num b := 3;
    CONST num ab := a + b;
    VAR num a_b := a + b;
    PERS num a__b := 5;
    VAR num counter := 100;

    PROC bump()
        counter := counter + 1;
    ENDPROC

    PROC main()
        TPWrite "ab=" \Num:=ab;
        TPWrite "a_b=" \Num:=a_b;
        TPWrite "a__b=" \Num:=a__b;
        bump;
        bump;
        TPWrite "counter=" \Num:=counter;
    ENDPROC
ENDMODULE
