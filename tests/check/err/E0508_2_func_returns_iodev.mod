! expect: E0508 line 5
! a FUNC returning iodev
MODULE E0508_2
  VAR iodev logfile;
  FUNC iodev get_log()
    RETURN logfile;
  ENDFUNC
ENDMODULE
