! expect: E0304 line 4
! a pose whose orient part has 3 components
MODULE E0304_3
  VAR pose frm := [[0,0,0],[1,0,0]];
ENDMODULE
