! expect: E0404 line 5
! \Num and \Bool are mutually exclusive in TPWrite
MODULE E0404_1
  PROC main()
    TPWrite "a" \Num:=1 \Bool:=TRUE;
  ENDPROC
ENDMODULE
