MODULE unused
  ! No CAB_TASK_MODULES instance names this file: no task loads it.
  PROC main()
    undefined_routine;
  ENDPROC
ENDMODULE
