! expect: E0201 line 10
! routine data of one routine used in another
MODULE E0201_4
  VAR num n;
  PROC first()
    VAR num tmp;
    tmp := 1;
  ENDPROC
  PROC second()
    n := tmp;
  ENDPROC
ENDMODULE
