! expect: E0126 line 4
! reserved words are case-insensitive: 'from' is FROM
MODULE E0126_2
  VAR num from := 1;
ENDMODULE
