! expect: W0203 line 6
! a call to a function that is not defined
MODULE W0203_1
  VAR num n;
  PROC main()
    n := Compute(2);
  ENDPROC
ENDMODULE
