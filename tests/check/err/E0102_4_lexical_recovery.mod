! expect: E0102 line 7
! expect: E0105 line 10
! expect: E0106 line 13
! expect: E0101 line 16
! error recovery: four lexical errors in different places, each reported
MODULE E0102_4
  VAR num this_identifier_has_33_characters;
  VAR num n;
  PROC first()
    TPWrite "tab\t";
  ENDPROC
  PROC second()
    n := 0x;
  ENDPROC
  PROC third()
    n := 1; @
  ENDPROC
ENDMODULE
