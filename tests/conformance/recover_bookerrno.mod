MODULE recover_bookerrno
    ! BookErrNo books a new system error number into a VAR errnum declared
    ! with -1 (manual 1.12, semantics 1.1); it can be raised and handled.
    VAR errnum ERR_MYGRIP := -1;
    VAR errnum ERR_MYVAC := -1;

    PROC grip()
        TPWrite "gripping";
        RAISE ERR_MYGRIP;
    ENDPROC

    PROC main()
        BookErrNo ERR_MYGRIP;
        BookErrNo ERR_MYVAC;
        TPWrite "booked " \Bool:=ERR_MYGRIP <> -1;
        TPWrite "distinct " \Bool:=ERR_MYGRIP <> ERR_MYVAC;
        TPWrite "outside 1..90 " \Bool:=ERR_MYVAC < 1 OR ERR_MYVAC > 90;
        RAISE ERR_MYVAC;
        grip;
        TPWrite "end";
    ERROR
        IF ERRNO = ERR_MYVAC THEN
            TPWrite "vacuum error";
            TRYNEXT;
        ELSEIF ERRNO = ERR_MYGRIP THEN
            TPWrite "gripper error";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
