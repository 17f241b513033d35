MODULE calendar_clock
    ! CDate is "YYYY-MM-DD", CTime "HH:MM:SS"; GetTime gives the weekday (1 = Monday
    ! to 7 = Sunday), hour, minute and second. The values change with the real date,
    ! so the shapes and ranges are checked.
    ! A day of waiting moves the date on. GetTaskName gives the running task.
    FUNC bool digits(string s, num start, num len)
        ! No character outside STR_DIGIT in the part: StrFind runs past its end.
        RETURN StrFind(StrPart(s, start, len), 1, STR_DIGIT \NotInSet) > len;
    ENDFUNC

    PROC main()
        VAR string date;
        VAR string time;
        VAR num taskno;
        date := CDate();
        time := CTime();
        TPWrite "date length " \Num:=StrLen(date);
        TPWrite "date dashes " \Bool:=StrPart(date, 5, 1) = "-" AND StrPart(date, 8, 1) = "-";
        TPWrite "date digits " \Bool:=digits(date, 1, 4) AND digits(date, 6, 2) AND digits(date, 9, 2);
        TPWrite "time length " \Num:=StrLen(time);
        TPWrite "time colons " \Bool:=StrPart(time, 3, 1) = ":" AND StrPart(time, 6, 1) = ":";
        TPWrite "time digits " \Bool:=digits(time, 1, 2) AND digits(time, 4, 2) AND digits(time, 7, 2);
        TPWrite "weekday " \Bool:=GetTime(\WDay) >= 1 AND GetTime(\WDay) <= 7;
        TPWrite "hour " \Bool:=GetTime(\Hour) >= 0 AND GetTime(\Hour) <= 23;
        TPWrite "minute " \Bool:=GetTime(\Min) >= 0 AND GetTime(\Min) <= 59;
        TPWrite "second " \Bool:=GetTime(\Sec) >= 0 AND GetTime(\Sec) <= 59;
        ! A day of controller time later the date has changed (the calendar clock
        ! follows controller time).
        WaitTime 86400;
        TPWrite "a day later " \Bool:=CDate() <> date AND StrLen(CDate()) = 10;
        TPWrite "task " + GetTaskName(\TaskNo:=taskno) + " number " \Num:=taskno;
    ENDPROC
ENDMODULE
