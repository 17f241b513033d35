! expect: E0408 line 6
! a function result passed to Incr
MODULE E0408_4
  VAR num n;
  PROC main()
    Incr Abs(n);
  ENDPROC
ENDMODULE
