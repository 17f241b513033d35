MODULE aux
  PROC main()
    report "main, cell loaded: " + ValToStr(ModExist("cell"));
  ENDPROC
ENDMODULE
