! expect: E0403 line 7
! Abs has no \Dec (Round has)
MODULE E0403_3
  VAR num n;
  PROC main()
    n := Round(2.5 \Dec:=1);
    n := Abs(-2 \Dec:=1);
  ENDPROC
ENDMODULE
