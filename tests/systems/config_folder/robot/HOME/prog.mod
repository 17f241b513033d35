MODULE prog
  PROC prog_main()
    VAR iodev log;
    ! HOME: is the HOME folder beside the configuration folder.
    Open "HOME:" \File:="prog.log", log \Write;
    Write log, greeting("T_ROB1");
    Close log;
    TPWrite greeting("T_ROB1");
    SetDO doProgDone, 1;
  ENDPROC
ENDMODULE
