! expect: E0509 line 4
! a RECORD with a component of its own type
MODULE E0509_1
  RECORD node
    num value;
    node next;
  ENDRECORD
ENDMODULE
