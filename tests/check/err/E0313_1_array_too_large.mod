! expect: E0313 line 5
! 1024 × 1025 elements: one row more than the 1048576 (2^20) every array may hold;
! the array above it holds exactly that many and is accepted
MODULE E0313_1
  VAR num a{1024,1025};
  VAR num fits{1024,1024};
ENDMODULE
