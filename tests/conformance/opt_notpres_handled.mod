MODULE opt_notpres_handled
    ! Using an optional parameter that was not passed raises ERR_NOTPRES
    ! (manual 1.1.5: check Present before use; semantics 1.3).
    PROC show(\num v)
        TPWrite "v=" \Num:=v;
    ERROR
        IF ERRNO = ERR_NOTPRES THEN
            TPWrite "v not present";
            RETURN;
        ENDIF
    ENDPROC

    PROC main()
        show \v:=1;
        show;
        TPWrite "done";
    ENDPROC
ENDMODULE
