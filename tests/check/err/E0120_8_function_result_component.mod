! expect: E0120 line 12
! expect: E0120 line 13
! a component and an element of a function's result: RAPID selects them of data only
MODULE E0120_8
  RECORD pair
    num a;
  ENDRECORD
  FUNC pair make()
    RETURN [1];
  ENDFUNC
  PROC main()
    TPWrite "a " \Num:=make().a;
    TPWrite "b " \Num:=make(){1};
  ENDPROC
ENDMODULE
