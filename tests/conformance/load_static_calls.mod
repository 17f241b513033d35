MODULE load_static_calls
  ! A loaded module may call a procedure of another loaded module by name. Once
  ! that module is unloaded the call reaches nothing: ERR_REFUNKPRC, as for a
  ! procedure defined nowhere (the error goes to the caller, main, whose handler
  ! takes it); loaded again, the call reaches it again.
  VAR iodev f;
  PROC main()
    Open "HOME:/A.mod", f \Write;
    Write f, "MODULE A";
    Write f, "PROC a_p() TPWrite ""in a""; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/B.mod", f \Write;
    Write f, "MODULE B";
    Write f, "PROC b_p() a_p; TPWrite ""b after a""; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load "HOME:/A.mod";
    Load "HOME:/B.mod";
    %"b_p"%;
    UnLoad "HOME:/A.mod";
    %"b_p"%;
    Load "HOME:/A.mod";
    %"b_p"%;
  ERROR
    TPWrite "err " \Bool:=ERRNO = ERR_REFUNKPRC;
    TRYNEXT;
  ENDPROC
ENDMODULE
