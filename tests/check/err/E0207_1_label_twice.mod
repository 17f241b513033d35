! expect: E0207 line 8
! two labels of one name
MODULE E0207_1
  VAR num n;
  PROC main()
  top:
    n := n + 1;
  top:
    n := n + 2;
  ENDPROC
ENDMODULE
