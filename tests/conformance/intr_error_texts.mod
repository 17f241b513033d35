MODULE intr_error_texts
    ! An error a handler takes leaves a warning in the program domain (manual 1.12);
    ! IError's trap reads it with ReadErrData. As on the controller the entry has a
    ! short title (an ErrWrite header holds at most 46 characters, RAPID instructions
    ! manual) and the detail in short strings, so a reporter that joins the title
    ! and a string into one line of its own (abb-motion-program-exec's
    ! error_reporter does) stays within a string's 80 characters.
    VAR intnum on_error;
    VAR num seen := 0;

    PROC main()
        VAR num z := 0;
        VAR string part;
        CONNECT on_error WITH report;
        IError PROGRAM_ERR, TYPE_ALL, on_error;
        reg1 := 1 / z;
        part := StrPart("abcd", 5, 2);
        WaitTime 0.1;
        TPWrite "reports " \Num:=seen;
    ERROR
        TRYNEXT;
    ENDPROC

    TRAP report
        VAR trapdata event;
        VAR errdomain domain;
        VAR num id;
        VAR errtype kind;
        VAR string title;
        VAR string str1;
        VAR string str2;
        VAR string line;
        GetTrapData event;
        ReadErrData event, domain, id, kind \Title:=title \Str1:=str1 \Str2:=str2;
        ! the reporter's own lines: these would raise ERR_STRTOOLNG on long texts
        line := "error title '" + title + "'";
        line := "error string '" + str1 + "'";
        TPWrite "program domain " \Bool:=domain = PROGRAM_ERR;
        TPWrite "a warning " \Bool:=kind = TYPE_WARN;
        TPWrite "title " + title;
        TPWrite "short title " \Bool:=StrLen(title) <= 46;
        TPWrite "detail " \Bool:=StrLen(str1) > 0 AND StrLen(str1) <= 40;
        Incr seen;
    ENDTRAP
ENDMODULE
