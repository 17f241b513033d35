! expect: E0105 line 6
! \07, \\ and \fF are fine; \4G has only one hex digit
MODULE E0105_3
  VAR string s;
  PROC main()
    s := "ok \07 \\ \fF but \4G";
  ENDPROC
ENDMODULE
