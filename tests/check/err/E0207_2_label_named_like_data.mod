! expect: E0207 line 7
! a label with the name of routine data
MODULE E0207_2
  PROC main()
    VAR num loop_start;
    loop_start := 0;
  loop_start:
    loop_start := loop_start + 1;
  ENDPROC
ENDMODULE
