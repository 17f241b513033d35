! expect: E0412 line 6
! MoveL's Speed is required: \Speed is wrong
MODULE E0412_1
  CONST robtarget p10 := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL p10, \Speed:=v100, z10, tool0;
  ENDPROC
ENDMODULE
