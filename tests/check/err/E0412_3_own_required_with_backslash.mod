! expect: E0412 line 8
! a required parameter of a user procedure passed with a backslash
MODULE E0412_3
  PROC show(num v)
    TPWrite "v: " \Num:=v;
  ENDPROC
  PROC main()
    show \v:=1;
  ENDPROC
ENDMODULE
