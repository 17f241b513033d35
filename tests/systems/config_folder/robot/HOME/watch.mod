MODULE watch
  PROC watch_main()
    WaitDO doProgDone, 1;
    TPWrite greeting("watcher");
  ENDPROC
ENDMODULE
