! expect: E0409 line 13
! a 2-dimensional array passed to a 1-dimensional parameter
MODULE E0409_2
  VAR num grid{2,2};
  VAR num row{2};
  PROC clear_row(VAR num vals{*})
    FOR i FROM 1 TO Dim(vals, 1) DO
      vals{i} := 0;
    ENDFOR
  ENDPROC
  PROC main()
    clear_row row;
    clear_row grid;
  ENDPROC
ENDMODULE
