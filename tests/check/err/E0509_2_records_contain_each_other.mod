! expect: E0509 line 5
! expect: E0509 line 9
! two RECORDs that contain each other: both contain themselves
MODULE E0509_2
  RECORD part
    num id;
    box holder;
  ENDRECORD
  RECORD box
    num id;
    part content;
  ENDRECORD
ENDMODULE
