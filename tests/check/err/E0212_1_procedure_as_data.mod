! expect: E0212 line 9
! a PROC name read as data
MODULE E0212_1
  VAR num n;
  PROC helper()
    TPWrite "helper";
  ENDPROC
  PROC main()
    n := helper + 1;
  ENDPROC
ENDMODULE
