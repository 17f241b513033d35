! expect: E0101 line 6
! an '@' after a statement; the character is skipped
MODULE E0101_1
  VAR num n;
  PROC main()
    n := 1; @
    n := n + 1;
  ENDPROC
ENDMODULE
