! expect: E0302 line 8
! pos + num is not defined (num * pos is)
MODULE E0302_1
  VAR pos p;
  VAR num n := 2;
  PROC main()
    p := n * p;
    p := p + n;
  ENDPROC
ENDMODULE
