! expect: E0305 line 11
! a component a user RECORD does not have
MODULE E0305_3
  RECORD pair
    num a;
    num b;
  ENDRECORD
  VAR pair pr;
  VAR num n;
  PROC main()
    n := pr.c;
  ENDPROC
ENDMODULE
