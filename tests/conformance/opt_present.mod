MODULE opt_present
    ! Optional parameters and Present (manual 1.1.5).
    PROC greet(string name \num times)
        IF Present(times) THEN
            FOR i FROM 1 TO times DO
                TPWrite "hello " + name;
            ENDFOR
        ELSE
            TPWrite "hi " + name;
        ENDIF
    ENDPROC

    PROC main()
        greet "bob";
        greet "amy" \times:=2;
        greet "joe";
    ENDPROC
ENDMODULE
