MODULE cell
  PROC cell_main()
    TPWrite task_label() + " cell_main, common loaded: " \Bool:=ModExist("common");
  ENDPROC
ENDMODULE
