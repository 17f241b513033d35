! expect: E0407 line 9
! \x?y where y is a routine variable
MODULE E0407_2
  PROC inner(\num x)
    IF Present(x) TPWrite "x: " \Num:=x;
  ENDPROC
  PROC outer()
    VAR num y := 1;
    inner \x?y;
  ENDPROC
ENDMODULE
