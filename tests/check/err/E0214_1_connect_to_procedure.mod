! expect: E0214 line 9
! CONNECT ... WITH a PROC
MODULE E0214_1
  VAR intnum ino;
  PROC helper()
    TPWrite "helper";
  ENDPROC
  PROC main()
    CONNECT ino WITH helper;
  ENDPROC
ENDMODULE
