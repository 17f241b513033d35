! expect: E0409 line 14
! a scalar passed to an array parameter
MODULE E0409_1
  VAR num k := 1;
  VAR num n;
  FUNC num total(num vals{*})
    VAR num acc := 0;
    FOR i FROM 1 TO Dim(vals, 1) DO
      acc := acc + vals{i};
    ENDFOR
    RETURN acc;
  ENDFUNC
  PROC main()
    n := total(k);
  ENDPROC
ENDMODULE
