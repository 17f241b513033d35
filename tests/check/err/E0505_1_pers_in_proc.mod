! expect: E0505 line 5
! a PERS inside a PROC
MODULE E0505_1
  PROC main()
    PERS num p := 1;
    TPWrite "main";
  ENDPROC
ENDMODULE
