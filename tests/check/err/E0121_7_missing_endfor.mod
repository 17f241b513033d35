! expect: E0121 line 6
! FOR without ENDFOR inside a FUNC
MODULE E0121_7
  FUNC num total()
    VAR num acc := 0;
    FOR i FROM 1 TO 3 DO
      acc := acc + i;
    RETURN acc;
  ENDFUNC
ENDMODULE
