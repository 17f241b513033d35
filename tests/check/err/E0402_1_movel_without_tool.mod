! expect: E0402 line 6
! MoveL without its Tool argument
MODULE E0402_1
  CONST robtarget p10 := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL p10, v100, z10;
  ENDPROC
ENDMODULE
