MODULE strfn_numtostr
    ! NumToStr (semantics 2.3 examples) and the manual's late-binding idiom
    ! "proc" + NumToStr(product_id, 0) of manual 1.1.5.
    PROC main()
        TPWrite NumToStr(0.38521, 3);
        TPWrite NumToStr(0.38521, 2 \Exp);
        FOR product_id FROM 1 TO 3 DO
            TPWrite "proc" + NumToStr(product_id, 0);
        ENDFOR
        TPWrite "n=" + NumToStr(42, 0);
    ENDPROC
ENDMODULE
