! expect: E0210 line 7
! a variable called like a function
MODULE E0210_2
  VAR num n;
  VAR num m;
  PROC main()
    n := m(2);
  ENDPROC
ENDMODULE
