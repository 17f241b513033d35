MODULE cfgdata_noconfig
    ! Without a system configuration (a module run on its own, not a backup), no
    ! instance is found and no domain can be saved.
    VAR string s := "unchanged";
    VAR num n := 7;
    VAR num idx := 0;

    PROC main()
        ReadCfgData "/EIO/EIO_SIGNAL/di1", "Device", s;
        TPWrite "after read: " + s;
        ReadCfgData "/EIO/EIO_SIGNAL/Device/d652", "Name", s \ListNo:=idx;
        TPWrite "list index still " \Num:=idx;
        WriteCfgData "/EIO/EIO_SIGNAL/di1", "Default", n;
        SaveCfgData "HOME:/eio.cfg", EIO_DOMAIN;
        SaveCfgData "HOME:", ALL_DOMAINS;
        TPWrite "END_OF_LIST is " \Num:=END_OF_LIST;
    ERROR
        IF ERRNO = ERR_CFG_NOTFND THEN
            TPWrite "ERR_CFG_NOTFND";
        ELSEIF ERRNO = ERR_CFG_ILL_DOMAIN THEN
            TPWrite "ERR_CFG_ILL_DOMAIN";
        ELSE
            TPWrite "other error";
        ENDIF
        TRYNEXT;
    ENDPROC
ENDMODULE
