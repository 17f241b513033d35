! expect: E0201 line 11
! expect: E0301 line 14
! expect: E0302 line 17
! expect: W0202 line 20
! error recovery: four independent semantic faults in four routines
MODULE E0201_5
  VAR num n;
  VAR string s;
  VAR pos p;
  PROC first()
    n := undeclared;
  ENDPROC
  PROC second()
    s := 5;
  ENDPROC
  PROC third()
    p := p + n;
  ENDPROC
  PROC fourth()
    NotDefinedAnywhere;
  ENDPROC
ENDMODULE
