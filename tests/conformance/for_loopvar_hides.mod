MODULE for_loopvar_hides
    ! The loop variable is implicitly declared and local to the loop; it hides
    ! a routine variable of the same name, which is unchanged afterwards
    ! (semantics 5, FOR).
    PROC main()
        VAR num i := 100;
        VAR string s := "";
        FOR i FROM 1 TO 3 DO
            s := s + ValToStr(i);
        ENDFOR
        TPWrite s;
        TPWrite "i=" \Num:=i;
    ENDPROC
ENDMODULE
