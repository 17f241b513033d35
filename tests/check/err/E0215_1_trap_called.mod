! expect: E0215 line 8
! a TRAP called like a procedure
MODULE E0215_1
  TRAP on_signal
    TPWrite "trap";
  ENDTRAP
  PROC main()
    on_signal;
  ENDPROC
ENDMODULE
