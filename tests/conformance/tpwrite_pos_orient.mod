MODULE tpwrite_pos_orient
    ! TPWrite \Pos and \Orient print an aggregate without blanks, each
    ! component in the num format (semantics 2.2).
    PROC main()
        VAR pos p1 := [1, 2, 3];
        VAR pos p2 := [2.5, -1, 0];
        VAR pos p3 := [10, 20, 30];
        TPWrite "p=" \Pos:=p1;
        TPWrite "q=" \Pos:=p2;
        TPWrite "sum=" \Pos:=p1 + p3;
        TPWrite "o=" \Orient:=[1, 0, 0, 0];
        TPWrite "h=" \Orient:=[0.5, 0.5, 0.5, 0.5];
    ENDPROC
ENDMODULE
