! expect: E0305 line 7
! pos has no component w
MODULE E0305_1
  VAR pos p;
  VAR num n;
  PROC main()
    n := p.w;
  ENDPROC
ENDMODULE
