! expect: E0602 line 5
! RETURN with a value in a TRAP
MODULE E0602_3
  TRAP on_tick
    RETURN 1;
  ENDTRAP
ENDMODULE
