MODULE load_erase
  ! EraseModule removes a module by name, however it was loaded (ERR_MODULE when
  ! no module has that name). CheckProgRef raises ERR_LINKREF while a loaded module
  ! uses data of a module that is gone; loading that module again links it anew.
  VAR iodev f;

  PROC main()
    Open "HOME:/lib.mod", f \Write;
    Write f, "MODULE lib";
    Write f, "VAR num base := 10;";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/user.mod", f \Write;
    Write f, "MODULE user";
    Write f, "PROC user_p() base := base + 1; TPWrite ""base="" \\Num:=base; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/helper.mod", f \Write;
    Write f, "MODULE helper";
    Write f, "PROC helper_p() TPWrite ""helper""; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    ! user needs lib: alone it does not link
    Load "HOME:/user.mod";
    Load "HOME:/lib.mod";
    Load "HOME:/user.mod";
    CheckProgRef;
    TPWrite "refs ok";
    %"user_p"%;
    EraseModule "lib";
    TPWrite "lib " \Bool:=ModExist("lib");
    CheckProgRef;
    ! \CheckRef checks the whole task, which has lost lib; without it, helper loads
    Load "HOME:/helper.mod" \CheckRef;
    Load "HOME:/helper.mod";
    TPWrite "helper " \Bool:=ModExist("helper");
    Load "HOME:/lib.mod";
    CheckProgRef;
    TPWrite "refs ok";
    %"user_p"%;
    EraseModule "HELPER";
    TPWrite "helper " \Bool:=ModExist("helper");
    %"helper_p"%;
    EraseModule "helper";
    TPWrite "end";
  ERROR
    IF ERRNO = ERR_LINKREF THEN
      TPWrite "ERR_LINKREF";
    ELSEIF ERRNO = ERR_MODULE THEN
      TPWrite "ERR_MODULE";
    ELSEIF ERRNO = ERR_REFUNKPRC THEN
      TPWrite "ERR_REFUNKPRC";
    ELSE
      TPWrite "other";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
