! expect: E0406 line 8
! an optional num parameter given without a value
MODULE E0406_2
  PROC show(\num val)
    IF Present(val) TPWrite "val: " \Num:=val;
  ENDPROC
  PROC main()
    show \val;
  ENDPROC
ENDMODULE
