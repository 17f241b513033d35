! expect: E0101 line 7
! a '$' in front of a number literal; the character is skipped
MODULE E0101_2
  VAR num cnt;
  PROC main()
    cnt := 0;
    cnt := $5;
  ENDPROC
ENDMODULE
