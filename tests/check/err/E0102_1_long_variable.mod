! expect: E0102 line 5
! a 33-character variable name (a 32-character one is fine)
MODULE E0102_1
  VAR num max_length_identifier_is_32chars;
  VAR num this_identifier_has_33_characters;
ENDMODULE
