! expect: E0412 line 5
! TPWrite's Num is optional: Num:= without backslash is wrong
MODULE E0412_2
  PROC main()
    TPWrite "a", Num:=5;
  ENDPROC
ENDMODULE
