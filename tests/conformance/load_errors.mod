MODULE load_errors
  ! The errors of Load and UnLoad, each taken by the ERROR handler by name.
  VAR iodev f;

  PROC main()
    Open "HOME:/good.mod", f \Write;
    Write f, "MODULE good";
    Write f, "  PROC good_p()";
    Write f, "    TPWrite ""good"";";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/bad.mod", f \Write;
    Write f, "MODULE bad";
    Write f, "  PROC bad_p()";
    Write f, "    x := ;";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/undef.mod", f \Write;
    Write f, "MODULE undef";
    Write f, "  PROC undef_p()";
    Write f, "    nowhere := 1;";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/callsnone.mod", f \Write;
    Write f, "MODULE callsnone";
    Write f, "  PROC callsnone_p()";
    Write f, "    missing_proc;";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/twin.mod", f \Write;
    Write f, "MODULE load_errors";
    Write f, "ENDMODULE";
    Close f;
    ! 1: no such file
    Load "HOME:/nofile.mod";
    ! 2: loads (FilePath and \File); 3: the same file again
    Load "HOME:" \File:="good.mod";
    Load "HOME:/good.mod";
    ! 4: a module named like one of the task's own
    Load "HOME:/twin.mod";
    ! 5: a module that does not check
    Load "HOME:/bad.mod";
    ! 6: data that is declared nowhere
    Load "HOME:/undef.mod";
    ! 7: a procedure defined nowhere links without \CheckRef ...
    Load "HOME:/callsnone.mod";
    UnLoad "HOME:/callsnone.mod";
    ! 8: ... and not with it
    Load "HOME:/callsnone.mod" \CheckRef;
    ! 9: a file that was not loaded
    UnLoad "HOME:/bad.mod";
    ! 10: FilePath and \File together
    UnLoad "HOME:" \File:="good.mod";
    TPWrite "good loaded " \Bool:=ModExist("good");
    TPWrite "bad loaded " \Bool:=ModExist("bad");
  ERROR
    IF ERRNO = ERR_FILNOTFND THEN
      TPWrite "ERR_FILNOTFND";
    ELSEIF ERRNO = ERR_LOADED THEN
      TPWrite "ERR_LOADED";
    ELSEIF ERRNO = ERR_SYNTAX THEN
      TPWrite "ERR_SYNTAX";
    ELSEIF ERRNO = ERR_LINKREF THEN
      TPWrite "ERR_LINKREF";
    ELSEIF ERRNO = ERR_UNLOAD THEN
      TPWrite "ERR_UNLOAD";
    ELSE
      TPWrite "other";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
