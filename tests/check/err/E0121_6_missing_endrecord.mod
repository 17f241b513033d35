! expect: E0121 line 4
! RECORD without ENDRECORD; a data declaration follows
MODULE E0121_6
  RECORD item
    num id;
    string name;
  VAR num n;
ENDMODULE
