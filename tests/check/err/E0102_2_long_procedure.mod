! expect: E0102 line 5
! a procedure name longer than 32 characters
MODULE E0102_2
  VAR num n;
  PROC process_the_incoming_part_from_the_feeder()
    n := 1;
  ENDPROC
ENDMODULE
