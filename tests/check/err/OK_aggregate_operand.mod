! an aggregate beside typed data takes that data's type (manual 1.3.3)
MODULE OK_aggregate_operand
  VAR pos p1 := [1,2,3];
  VAR pos p2;
  VAR orient o := [1,0,0,0];
  PROC main()
    p2 := [10,10,30] + p1;
    p2 := p1 + [10,10,30];
    p2 := p1 - ([1,1,1]) + [0,0,1];
    o := o * [0,0,0,1];
    o := OrientZYX(90,0,0) * [0,0,0,1];
    IF p1 = [1,2,3] THEN
      p2 := p1 * [0,0,1];
    ENDIF
  ENDPROC
ENDMODULE
