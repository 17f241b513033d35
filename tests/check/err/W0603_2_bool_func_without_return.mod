! expect: W0603 line 4
! a bool FUNC whose body only writes
MODULE W0603_2
  FUNC bool check(num v)
    TPWrite "check: " \Num:=v;
  ENDFUNC
ENDMODULE
