! expect: E0212 line 8
! a FUNC name used as data (no argument list)
MODULE E0212_2
  FUNC num f()
    RETURN 1;
  ENDFUNC
  PROC main()
    TPWrite "f: " \Num:=f;
  ENDPROC
ENDMODULE
