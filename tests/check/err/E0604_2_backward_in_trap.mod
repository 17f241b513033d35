! expect: E0604 line 6
! a BACKWARD handler in a TRAP
MODULE E0604_2
  TRAP on_tick
    TPWrite "tick";
  BACKWARD
    TPWrite "back";
  ENDTRAP
ENDMODULE
