! expect: E0103 line 5
! the limit counts characters of the value: \41 and "" are one character each
MODULE E0103_2
  VAR string ok80 := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\41""b";
  VAR string bad81 := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\41""b";
ENDMODULE
