! expect: E0309 line 5
! an assignment to the read-only ERRNO
MODULE E0309_3
  PROC main()
    ERRNO := 0;
  ENDPROC
ENDMODULE
