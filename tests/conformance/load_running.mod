MODULE load_running
  ! A module whose routine is running cannot be unloaded (ERR_UNLOAD); once the
  ! routine has returned it can. EraseModule refuses the same way.
  VAR iodev f;

  PROC main()
    Open "HOME:/self.mod", f \Write;
    Write f, "MODULE self";
    Write f, "  PROC self_p()";
    Write f, "    UnLoad ""HOME:/self.mod"";";
    Write f, "  ERROR";
    Write f, "    IF ERRNO = ERR_UNLOAD TPWrite ""still running"";";
    Write f, "    TRYNEXT;";
    Write f, "  ENDPROC";
    Write f, "  PROC self_e()";
    Write f, "    EraseModule ""self"";";
    Write f, "  ERROR";
    Write f, "    IF ERRNO = ERR_UNLOAD TPWrite ""erase refused"";";
    Write f, "    TRYNEXT;";
    Write f, "  ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load "HOME:/self.mod";
    %"self_p"%;
    %"self_e"%;
    TPWrite "loaded " \Bool:=ModExist("self");
    UnLoad "HOME:/self.mod";
    TPWrite "loaded " \Bool:=ModExist("self");
    ! The task's own running module cannot be erased either.
    EraseModule "load_running";
  ERROR
    IF ERRNO = ERR_UNLOAD THEN
      TPWrite "main running";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
