MODULE wait_args_once
  ! A call's arguments are evaluated once, when the call is made: traps running
  ! during a wait (§1.11) do not make WaitTime evaluate its time again.
  VAR num calls := 0;
  VAR num ticks := 0;
  VAR intnum tick;
  VAR clock c;

  FUNC num Seconds(num s)
    calls := calls + 1;
    RETURN s;
  ENDFUNC

  TRAP OnTick
    ticks := ticks + 1;
  ENDTRAP

  PROC main()
    CONNECT tick WITH OnTick;
    ITimer 0.1, tick;
    ClkStart c;
    WaitTime Seconds(0.55);
    ClkStop c;
    IDelete tick;
    TPWrite "calls " \Num:=calls;
    TPWrite "ticks " \Num:=ticks;
    TPWrite "waited " \Num:=Round(ClkRead(c) \Dec:=2);
  ENDPROC
ENDMODULE
