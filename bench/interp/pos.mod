MODULE BenchPos
  ! Benchmark 5: 3*10^5 rounds of pos arithmetic: aggregate, pos + pos, num * pos,
  ! pos * pos (cross product), DotProd and component access. All components stay small
  ! exact integers.

  PROC main()
    VAR pos a;
    VAR pos b;
    VAR pos c;
    VAR num d;
    VAR num chk := 0;
    FOR i FROM 1 TO 1000 DO
      FOR j FROM 1 TO 300 DO
        a := [i MOD 13, j MOD 11, (i + j) MOD 7];
        b := [j MOD 5, 3, i MOD 9];
        c := 2 * (a + b);
        c := c * a;
        d := DotProd(c, b);
        chk := (chk + d + c.x + c.y + c.z + 100000) MOD 999983;
      ENDFOR
    ENDFOR
    TPWrite "pos chk=" \Num:=chk;
  ENDPROC
ENDMODULE
