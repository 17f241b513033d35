! expect: E0214 line 9
! CONNECT ... WITH a FUNC
MODULE E0214_3
  VAR intnum ino;
  FUNC num handler()
    RETURN 0;
  ENDFUNC
  PROC main()
    CONNECT ino WITH handler;
  ENDPROC
ENDMODULE
