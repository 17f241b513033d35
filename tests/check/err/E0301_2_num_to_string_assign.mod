! expect: E0301 line 6
! a num assigned to a string
MODULE E0301_2
  VAR string s;
  PROC main()
    s := 5;
  ENDPROC
ENDMODULE
