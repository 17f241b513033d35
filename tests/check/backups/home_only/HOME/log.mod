MODULE log
  PROC log_main()
    report "log_main, common loaded: " + ValToStr(ModExist("common"));
  ENDPROC
ENDMODULE
