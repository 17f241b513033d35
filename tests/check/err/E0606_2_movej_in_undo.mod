! expect: E0606 line 9
! MoveJ in an UNDO handler
MODULE E0606_2
  CONST robtarget p10 := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ p10, v100, z10, tool0;
  UNDO
    TPWrite "undo";
    MoveJ p10, v100, fine, tool0 \WObj:=wobj0;
  ENDPROC
ENDMODULE
