MODULE pos_aggregate_operand
  ! An aggregate beside typed data takes that data's type (manual 1.3.3: the
  ! context types the aggregate; the other operand of a binary operator is its
  ! context). Values worked out from the operator table of manual 1.3.1.
  ALIAS pos mypos;
  PROC main()
    VAR pos p1 := [1,2,3];
    VAR pos p2;
    VAR mypos a := [5,5,5];
    VAR orient o := [1,0,0,0];
    VAR orient h := [0.5,0.5,0.5,0.5];
    ! [10,10,30] + [1,2,3] = [11,12,33]
    p2 := [10,10,30] + p1;
    TPWrite "agg+p " \Pos:=p2;
    p2 := p1 + [10,10,30];
    TPWrite "p+agg " \Pos:=p2;
    ! [10,10,30] - [1,2,3] = [9,8,27]; [1,2,3] - [1,1,1] = [0,1,2]
    p2 := [10,10,30] - p1;
    TPWrite "agg-p " \Pos:=p2;
    p2 := p1 - ([1,1,1]);
    TPWrite "p-(agg) " \Pos:=p2;
    ! cross products: [1,2,3] x [0,0,1] = [2,-1,0]; [0,0,1] x [1,2,3] = [-2,1,0]
    p2 := p1 * [0,0,1];
    TPWrite "p*agg " \Pos:=p2;
    p2 := [0,0,1] * p1;
    TPWrite "agg*p " \Pos:=p2;
    ! an alias of pos types the aggregate as its base type: [5,5,5] + [1,0,-1]
    p2 := a + [1,0,-1];
    TPWrite "alias " \Pos:=p2;
    ! a chain: ([1,2,3] + [1,1,1]) + [0,0,10] = [2,3,14]
    p2 := p1 + [1,1,1] + [0,0,10];
    TPWrite "chain " \Pos:=p2;
    ! the unit quaternion times k is k
    o := o * [0,0,0,1];
    TPWrite "o*agg " \Orient:=o;
    ! (0.5 + 0.5i + 0.5j + 0.5k) * i = -0.5 + 0.5i + 0.5j - 0.5k
    o := h * [0,1,0,0];
    TPWrite "h*agg " \Orient:=o;
    ! i * (0.5 + 0.5i + 0.5j + 0.5k) = -0.5 + 0.5i - 0.5j + 0.5k
    o := [0,1,0,0] * h;
    TPWrite "agg*h " \Orient:=o;
    ! comparisons with an aggregate on either side
    IF [1,2,3] = p1 THEN
      TPWrite "agg=p";
    ENDIF
    IF p1 <> [1,2,4] THEN
      TPWrite "p<>agg";
    ENDIF
  ENDPROC
ENDMODULE
