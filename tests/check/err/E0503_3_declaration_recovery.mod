! expect: E0503 line 7
! expect: E0504 line 8
! expect: E0127 line 9
! expect: E0205 line 12
! error recovery: four independent declaration faults
MODULE E0503_3
  LOCAL PERS num lp;
  CONST num c;
  VAR num grid{2,2,2,2};
  PROC main()
    VAR num t;
    VAR bool t;
    TPWrite "main";
  ENDPROC
ENDMODULE
