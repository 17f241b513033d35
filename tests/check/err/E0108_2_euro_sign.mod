! expect: E0108 line 5
! UTF-8 file; 'é' is Latin-1, the euro sign is not
MODULE E0108_2
  VAR string ok := "café";
  VAR string price := "5 €";
ENDMODULE
