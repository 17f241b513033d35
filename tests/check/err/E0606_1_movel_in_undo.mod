! expect: E0606 line 8
! MoveL in an UNDO handler
MODULE E0606_1
  CONST robtarget p10 := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL p10, v100, fine, tool0;
  UNDO
    MoveL p10, v100, fine, tool0;
  ENDPROC
ENDMODULE
