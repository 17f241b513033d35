! expect: E0105 line 5
! there are no C escapes: \n is an error
MODULE E0105_2
  PROC main()
    TPWrite "line\n";
  ENDPROC
ENDMODULE
