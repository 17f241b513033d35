MODULE lex_comments
    ! Comments start with ! and run to the end of the line (manual 1.1.2);
    ! a ! inside a string literal is not a comment.
    PROC main()
        VAR num x := 1; ! trailing comment
        ! x := 2;
        TPWrite "x=" \Num:=x;
        TPWrite "bang! not a comment";
    ENDPROC
ENDMODULE
