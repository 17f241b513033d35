! expect: E0302 line 9
! only = and <> compare strings
MODULE E0302_2
  VAR string s1 := "a";
  VAR string s2 := "b";
  VAR bool b;
  PROC main()
    b := s1 = s2;
    b := s1 < s2;
  ENDPROC
ENDMODULE
