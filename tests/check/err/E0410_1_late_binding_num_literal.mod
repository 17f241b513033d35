! expect: E0410 line 5
! % 5 % names no procedure
MODULE E0410_1
  PROC main()
    % 5 %;
  ENDPROC
ENDMODULE
