! expect: E0409 line 9
! an array passed to a scalar parameter
MODULE E0409_3
  VAR num arr{3};
  PROC show(num v)
    TPWrite "v: " \Num:=v;
  ENDPROC
  PROC main()
    show arr;
  ENDPROC
ENDMODULE
