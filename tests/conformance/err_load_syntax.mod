MODULE err_load_syntax
  ! A module that does not check is refused with ERR_SYNTAX; no handler takes it,
  ! so the program stops. The message quotes the checker's diagnostic with its
  ! file, line and column.
  VAR iodev f;

  PROC main()
    Open "HOME:/broken.mod", f \Write;
    Write f, "MODULE broken";
    Write f, "  PROC broken_p()";
    Write f, "    x := ;";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    TPWrite "loading";
    Load "HOME:/broken.mod";
    TPWrite "not reached";
  ENDPROC
ENDMODULE
