! expect: E0609 line 9
! CONNECT to a CONST intnum
MODULE E0609_2
  CONST intnum cino := 0;
  TRAP on_tick
    TPWrite "tick";
  ENDTRAP
  PROC main()
    CONNECT cino WITH on_tick;
  ENDPROC
ENDMODULE
