! expect: E0408 line 13
! part of a persistent passed to a user routine's INOUT parameter (the manual: a
! variable, or an entire persistent); built-ins such as Incr take one (line 12)
MODULE E0408_5
  PERS num ptr{2} := [0, 0];
  PERS num whole := 0;
  PROC bump(INOUT num n)
    n := n + 1;
  ENDPROC
  PROC main()
    bump whole;
    Incr ptr{1};
    bump ptr{2};
  ENDPROC
ENDMODULE
