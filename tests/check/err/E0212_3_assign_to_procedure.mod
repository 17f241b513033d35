! expect: E0212 line 8
! an assignment to a procedure name
MODULE E0212_3
  PROC helper()
    TPWrite "helper";
  ENDPROC
  PROC main()
    helper := 1;
  ENDPROC
ENDMODULE
