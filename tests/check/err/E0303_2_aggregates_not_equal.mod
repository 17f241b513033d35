! expect: E0303 line 6
! two aggregates compared with <> in an assignment
MODULE E0303_2
  VAR bool b;
  PROC main()
    b := [0,0,0] <> [1,1,1];
  ENDPROC
ENDMODULE
