MODULE load_basic
  ! Load links a module file into the running task; its procedures are reached by
  ! late binding and its data starts with its initial values (manual 1.6, 1.17).
  ! After UnLoad, late binding no longer finds the procedure: ERR_REFUNKPRC.
  VAR iodev f;
  VAR num n := 5;

  PROC main()
    Open "HOME:/ext.mod", f \Write;
    Write f, "MODULE ext";
    Write f, "  VAR num count := 40;";
    Write f, "  PERS string tag := ""x"";";
    Write f, "  PROC ext_hello(num k)";
    Write f, "    count := count + k;";
    Write f, "    TPWrite ""ext count="" \\Num:=count;";
    Write f, "  ENDPROC";
    Write f, "  PROC ext_1() TPWrite ""by var""; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    TPWrite "before " \Bool:=ModExist("ext");
    Load \Dynamic, "HOME:/ext.mod";
    TPWrite "after " \Bool:=ModExist("ext");
    ! ModTimeDnum of a loaded module is the time of the file it came from.
    TPWrite "time " \Bool:=ModTimeDnum("ext") = FileTimeDnum("HOME:/ext.mod" \ModifyTime);
    %"ext_hello"% 2;
    %"ext_hello"% n;
    ! A module-qualified name reaches the procedure too, as public programs use it.
    %"ext:ext_hello"% 1;
    CallByVar "ext_", 1;
    UnLoad "HOME:/ext.mod";
    TPWrite "unloaded " \Bool:=ModExist("ext");
    %"ext_hello"% 1;
  ERROR
    IF ERRNO = ERR_REFUNKPRC THEN
      TPWrite "gone";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
