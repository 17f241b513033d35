MODULE load_session
  ! StartLoad reads a module while the program goes on; WaitLoad links it (and
  ! with \UnloadPath first unloads another); CancelLoad drops a load under way.
  ! A loadsession that has no load under way is refused: ERR_UNKPROC in WaitLoad,
  ! ERR_LOADNO_NOUSE in CancelLoad; a missing file already fails in StartLoad.
  VAR iodev f;
  VAR loadsession s1;
  VAR loadsession s2;

  PROC main()
    Open "HOME:/one.mod", f \Write;
    Write f, "MODULE one";
    Write f, "PROC one_p() TPWrite ""one""; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/two.mod", f \Write;
    Write f, "MODULE two";
    Write f, "PROC two_p() TPWrite ""two""; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    StartLoad \Dynamic, "HOME:/one.mod", s1;
    TPWrite "started " \Bool:=ModExist("one");
    WaitLoad s1;
    TPWrite "waited " \Bool:=ModExist("one");
    %"one_p"%;
    StartLoad "HOME:" \File:="two.mod", s2;
    WaitLoad \UnloadPath:="HOME:/one.mod", s2;
    TPWrite "one " \Bool:=ModExist("one");
    %"two_p"%;
    ! s2 was used up by WaitLoad
    WaitLoad s2;
    CancelLoad s2;
    StartLoad "HOME:/one.mod", s1;
    CancelLoad s1;
    TPWrite "cancelled " \Bool:=ModExist("one");
    StartLoad "HOME:/none.mod", s1;
    TPWrite "end";
  ERROR
    IF ERRNO = ERR_UNKPROC THEN
      TPWrite "ERR_UNKPROC";
    ELSEIF ERRNO = ERR_LOADNO_NOUSE THEN
      TPWrite "ERR_LOADNO_NOUSE";
    ELSEIF ERRNO = ERR_FILNOTFND THEN
      TPWrite "ERR_FILNOTFND";
    ELSE
      TPWrite "other";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
