! expect: E0120 line 7
! relational operators do not chain: <relation> has at most one relop
MODULE E0120_3
  VAR num n;
  VAR bool b;
  PROC main()
    b := n < 5 < 7;
  ENDPROC
ENDMODULE
