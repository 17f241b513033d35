! expect: E0305 line 7
! orient has q1..q4, not x
MODULE E0305_2
  VAR robtarget rt;
  PROC main()
    rt.trans.x := 0;
    rt.rot.x := 0;
  ENDPROC
ENDMODULE
