! expect: E0201 line 6
! m is not declared
MODULE E0201_1
  VAR num n;
  PROC main()
    n := m + 1;
  ENDPROC
ENDMODULE
