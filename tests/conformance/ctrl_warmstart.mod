MODULE ctrl_warmstart
  ! WarmStart restarts the controller. `rapid run` does not start the program again
  ! (it would run forever): the run ends at WarmStart like a stop, exit status 0,
  ! and stderr says a warm start was requested (docs/semantics.md).
  PROC main()
    TPWrite "parameters written";
    WarmStart;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
