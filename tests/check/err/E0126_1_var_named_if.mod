! expect: E0126 line 4
! IF is reserved
MODULE E0126_1
  VAR num IF;
ENDMODULE
