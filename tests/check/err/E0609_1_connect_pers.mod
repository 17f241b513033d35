! expect: E0609 line 9
! CONNECT to a PERS intnum
MODULE E0609_1
  PERS intnum pino := 0;
  TRAP on_tick
    TPWrite "tick";
  ENDTRAP
  PROC main()
    CONNECT pino WITH on_tick;
  ENDPROC
ENDMODULE
