! expect: E0214 line 7
! CONNECT ... WITH a variable
MODULE E0214_2
  VAR intnum ino;
  VAR num handler;
  PROC main()
    CONNECT ino WITH handler;
  ENDPROC
ENDMODULE
