! expect: E0608 line 7
! RAISE without a number in a TRAP body, inside an IF
MODULE E0608_2
  VAR bool failed;
  TRAP on_tick
    IF failed THEN
      RAISE;
    ENDIF
  ENDTRAP
ENDMODULE
