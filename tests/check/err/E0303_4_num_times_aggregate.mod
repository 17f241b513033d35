! expect: E0303 line 6
! a num beside an aggregate gives it no type: only records and arrays are aggregates
MODULE E0303_4
  VAR pos p;
  PROC main()
    p := 2 * [1,2,3];
  ENDPROC
ENDMODULE
