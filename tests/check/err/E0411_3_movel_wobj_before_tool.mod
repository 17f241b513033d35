! expect: E0411 line 7
! MoveL's \WObj comes after Tool
MODULE E0411_3
  CONST robtarget p10 := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveL p10, v100, z10, tool0 \WObj:=wobj0;
    MoveL p10, v100, z10 \WObj:=wobj0, tool0;
  ENDPROC
ENDMODULE
