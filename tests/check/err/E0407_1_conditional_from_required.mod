! expect: E0407 line 8
! \x?y where y is a required parameter
MODULE E0407_1
  PROC inner(\num x)
    IF Present(x) TPWrite "x: " \Num:=x;
  ENDPROC
  PROC outer(num y)
    inner \x?y;
  ENDPROC
ENDMODULE
