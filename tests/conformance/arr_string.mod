MODULE arr_string
    ! Array of strings; uninitialised elements are empty strings.
    PROC main()
        VAR string names{4} := ["pick", "place", "home", ""];
        VAR string joined := "";
        VAR string blank{2};
        FOR i FROM 1 TO 3 DO
            joined := joined + names{i};
            IF i < 3 joined := joined + "/";
        ENDFOR
        TPWrite joined;
        TPWrite "len4=" \Num:=StrLen(names{4});
        TPWrite "blank=" \Num:=StrLen(blank{1} + blank{2});
        names{4} := names{1} + names{2};
        TPWrite names{4};
    ENDPROC
ENDMODULE
