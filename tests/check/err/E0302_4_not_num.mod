! expect: E0302 line 7
! NOT applied to a num
MODULE E0302_4
  VAR num n;
  VAR bool b;
  PROC main()
    b := NOT n;
  ENDPROC
ENDMODULE
