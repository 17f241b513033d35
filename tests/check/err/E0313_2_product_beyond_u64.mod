! expect: E0313 line 4
! 1e7 in each of three dimensions: 1e21 elements, more than any integer count holds
MODULE E0313_2
  VAR num a{10000000,10000000,10000000};
ENDMODULE
