! expect: E0307 line 7
! iodev values compared with <>
MODULE E0307_4
  VAR iodev f1;
  VAR iodev f2;
  PROC main()
    IF f1 <> f2 TPWrite "different";
  ENDPROC
ENDMODULE
