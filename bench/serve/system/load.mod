MODULE load
  ! The program the load test runs while clients poll: it counts on the group output
  ! go_seq every 20 ms (1, 2, 3 … 65535, 1 …), so that each subscriber can tell a
  ! lost or reordered event from the values it is told.
  VAR num n := 0;
  PROC main()
    WHILE TRUE DO
      n := n + 1;
      IF n > 65535 n := 1;
      SetGO go_seq, n;
      WaitTime 0.02;
    ENDWHILE
  ENDPROC
ENDMODULE
