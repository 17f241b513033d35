MODULE fmt_tpwrite_pos
    ! FORMAT-DEPENDENT. \Pos and \Orient components use the 6-digit num
    ! format (semantics 2.2), with no blanks between components.
    PROC main()
        VAR pos p := [1 / 3, 2, 1E10];
        VAR orient o := [0.7071068, 0, 0, 0.7071068];
        TPWrite "p=" \Pos:=p;
        TPWrite "o=" \Orient:=o;
        p.x := -2 / 3;
        TPWrite "p=" \Pos:=p;
    ENDPROC
ENDMODULE
