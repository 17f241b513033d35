MODULE str_concat
    ! String concatenation with + (manual 1.3.1: "IN" + "PUT" gives "INPUT").
    PROC main()
        VAR string a := "IN";
        VAR string b := "PUT";
        VAR string s;
        s := a + b;
        TPWrite s;
        TPWrite "IN" + "PUT";
        s := s + "" + "!";
        TPWrite s;
        s := "";
        FOR i FROM 1 TO 3 DO
            s := s + "ab";
        ENDFOR
        TPWrite s;
        TPWrite "len=" \Num:=StrLen(s);
        TPWrite "[" + "" + "]";
    ENDPROC
ENDMODULE
