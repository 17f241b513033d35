MODULE common
  ! Loaded into T_LOG and T_AUX: -Task given twice.
  PROC report(string what)
    TPWrite task_label() + " " + what;
  ENDPROC
ENDMODULE
