MODULE load_save
  ! Save writes a module with the current values of its persistents (manual
  ! 1.2.2); UnLoad \ErrIfChanged refuses a module whose persistents changed since
  ! it was loaded or saved (ERR_NOTSAVED); UnLoad \Save writes it back first.
  VAR iodev f;
  VAR string line;

  PROC main()
    Open "HOME:/keep.mod", f \Write;
    Write f, "MODULE keep";
    Write f, "PERS num counter := 1;";
    Write f, "PROC keep_bump() counter := counter + 1; ENDPROC";
    Write f, "PROC keep_show() TPWrite ""counter="" \\Num:=counter; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load "HOME:/keep.mod";
    %"keep_bump"%;
    UnLoad \ErrIfChanged, "HOME:/keep.mod";
    Save "keep" \FilePath:="HOME:/copy.mod";
    UnLoad \ErrIfChanged, "HOME:/keep.mod";
    ! keep.mod itself was not written: loading it again starts from 1
    Load "HOME:/keep.mod";
    %"keep_show"%;
    %"keep_bump"%;
    %"keep_bump"%;
    UnLoad \Save, "HOME:/keep.mod";
    Load "HOME:/keep.mod";
    %"keep_show"%;
    UnLoad "HOME:/keep.mod";
    Load "HOME:/copy.mod";
    %"keep_show"%;
    Open "HOME:/copy.mod", f \Read;
    line := ReadStr(f);
    TPWrite line;
    line := ReadStr(f);
    TPWrite line;
    Close f;
    Save "nosuch";
  ERROR
    IF ERRNO = ERR_NOTSAVED THEN
      TPWrite "ERR_NOTSAVED";
    ELSEIF ERRNO = ERR_MODULE THEN
      TPWrite "ERR_MODULE";
    ELSE
      TPWrite "other";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
