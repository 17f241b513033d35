! expect: W0605 line 19
! Break inside a loop of an UNDO handler ends the loop (RW 6.15): no warning. Stop,
! RAISE and RETURN in a routine the handler calls are not written in the handler:
! only the RETURN written in the handler itself is reported.
MODULE W0605_6
  VAR num n;
  PROC cleanup()
    IF n = 0 RETURN;
    Stop;
    RAISE 5;
  ENDPROC
  PROC main()
    n := 1;
  UNDO
    WHILE TRUE DO
      Break;
    ENDWHILE
    cleanup;
    RETURN;
  ENDPROC
ENDMODULE
