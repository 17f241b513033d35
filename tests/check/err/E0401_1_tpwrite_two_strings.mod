! expect: E0401 line 5
! TPWrite has one required parameter
MODULE E0401_1
  PROC main()
    TPWrite "a", "b";
  ENDPROC
ENDMODULE
