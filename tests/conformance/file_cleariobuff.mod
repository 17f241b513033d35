MODULE file_cleariobuff
    ! ClearIOBuff discards input waiting on a serial channel; a file keeps what is not
    ! read yet, so on an open file it changes nothing. On an iodev that is not open it
    ! raises ERR_FILEACC, as Rewind does (docs/semantics.md).
    VAR iodev f;

    PROC main()
        Open "HOME:/c.txt", f \Write;
        Write f, "first";
        Write f, "second";
        Close f;
        Open "HOME:/c.txt", f \Read;
        TPWrite ReadStr(f);
        ClearIOBuff f;
        TPWrite ReadStr(f);
        Close f;
        ClearIOBuff f;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEACC THEN
            TPWrite "closed: ERR_FILEACC";
            rewind_closed;
            RETURN;
        ENDIF
    ENDPROC

    PROC rewind_closed()
        Rewind f;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEACC TPWrite "rewind closed: ERR_FILEACC";
        RETURN;
    ENDPROC
ENDMODULE
