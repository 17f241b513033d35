! expect: E0205 line 5
! two module variables whose names differ only in case
MODULE E0205_1
  VAR num count;
  VAR bool COUNT;
ENDMODULE
