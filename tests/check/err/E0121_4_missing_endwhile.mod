! expect: E0121 line 6
! WHILE without ENDWHILE
MODULE E0121_4
  VAR num n;
  PROC main()
    WHILE n < 10 DO
      n := n + 1;
  ENDPROC
ENDMODULE
