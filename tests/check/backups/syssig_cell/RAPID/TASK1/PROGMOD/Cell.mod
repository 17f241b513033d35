MODULE Cell
  ! A cell program a PLC stops and starts through system inputs. Two timer
  ! interrupts are ordered: one \SingleSafe (kept across a program stop), one
  ! \Single (dropped when it comes due while the program stands).
  VAR clock cycle;
  VAR intnum safeTimer;
  VAR intnum plainTimer;

  PROC main()
    ClkStart cycle;
    CONNECT safeTimer WITH onSafe;
    CONNECT plainTimer WITH onPlain;
    ITimer \SingleSafe, 1.5, safeTimer;
    ITimer \Single, 1.8, plainTimer;
    WaitTime 3;
    TPWrite "waited until " \Num:=Round(ClkRead(cycle) \Dec:=2);
  ENDPROC

  PROC on_stop()
    TPWrite "STOP event at " \Num:=Round(ClkRead(cycle) \Dec:=2);
  ENDPROC

  PROC on_restart()
    TPWrite "RESTART event at " \Num:=Round(ClkRead(cycle) \Dec:=2);
  ENDPROC

  TRAP onSafe
    TPWrite "safe trap at " \Num:=Round(ClkRead(cycle) \Dec:=2);
  ENDTRAP

  TRAP onPlain
    TPWrite "plain trap at " \Num:=Round(ClkRead(cycle) \Dec:=2);
  ENDTRAP
ENDMODULE
