MODULE late_binding_basic
    ! Late binding (manual 1.1.5): % "proc" + NumToStr(product_id, 0) % args.
    PROC proc1(num x)
        TPWrite "proc1 " \Num:=x;
    ENDPROC

    PROC proc2(num x)
        TPWrite "proc2 " \Num:=x;
    ENDPROC

    PROC proc3(num x)
        TPWrite "proc3 " \Num:=x;
    ENDPROC

    PROC main()
        FOR product_id FROM 1 TO 3 DO
            % "proc" + NumToStr(product_id, 0) % product_id * 10;
        ENDFOR
        % "proc" + "2" % 0;
    ENDPROC
ENDMODULE
