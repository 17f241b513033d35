! expect: W0605 line 14
! expect: W0605 line 16
! expect: W0605 line 18
! expect: W0605 line 20
! Stop with a switch, and the four instructions nested in IF/TEST/compact IF of an UNDO handler
MODULE W0605_5
  VAR num n;
  PROC main()
    n := 1;
    EXIT;
  UNDO
    TEST n
    CASE 1:
      Stop \NoRegain;
    DEFAULT:
      Break;
    ENDTEST
    IF n > 0 RETURN;
    IF n > 0 THEN
      RAISE 5;
    ENDIF
  ENDPROC
ENDMODULE
