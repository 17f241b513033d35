! expect: E0310 line 6
! WHILE with a num condition
MODULE E0310_2
  VAR num n := 3;
  PROC main()
    WHILE n DO
      n := n - 1;
    ENDWHILE
  ENDPROC
ENDMODULE
