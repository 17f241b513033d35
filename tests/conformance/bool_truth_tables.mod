MODULE bool_truth_tables
    ! The truth tables of AND, OR, XOR and NOT (manual 1.3.1).
    PROC main()
        VAR bool t := TRUE;
        VAR bool f := FALSE;
        TPWrite "T AND T " \Bool:=t AND t;
        TPWrite "T AND F " \Bool:=t AND f;
        TPWrite "F AND T " \Bool:=f AND t;
        TPWrite "F AND F " \Bool:=f AND f;
        TPWrite "T OR T " \Bool:=t OR t;
        TPWrite "T OR F " \Bool:=t OR f;
        TPWrite "F OR T " \Bool:=f OR t;
        TPWrite "F OR F " \Bool:=f OR f;
        TPWrite "T XOR T " \Bool:=t XOR t;
        TPWrite "T XOR F " \Bool:=t XOR f;
        TPWrite "F XOR T " \Bool:=f XOR t;
        TPWrite "F XOR F " \Bool:=f XOR f;
        TPWrite "NOT T " \Bool:=NOT t;
        TPWrite "NOT F " \Bool:=NOT f;
    ENDPROC
ENDMODULE
