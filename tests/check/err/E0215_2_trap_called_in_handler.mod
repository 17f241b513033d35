! expect: E0215 line 11
! a TRAP called from an ERROR handler
MODULE E0215_2
  VAR num n;
  TRAP on_error
    TPWrite "trap";
  ENDTRAP
  PROC main()
    n := 1;
  ERROR
    on_error;
    TRYNEXT;
  ENDPROC
ENDMODULE
