! expect: E0205 line 5
! routine data with the name of a parameter
MODULE E0205_4
  PROC setup(num a)
    VAR num a;
    TPWrite "setup";
  ENDPROC
ENDMODULE
