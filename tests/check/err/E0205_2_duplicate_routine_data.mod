! expect: E0205 line 6
! two routine variables of one name
MODULE E0205_2
  PROC main()
    VAR num a;
    VAR string a;
    TPWrite "main";
  ENDPROC
ENDMODULE
