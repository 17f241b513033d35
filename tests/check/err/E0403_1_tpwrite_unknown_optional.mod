! expect: E0403 line 5
! TPWrite has no \Foo
MODULE E0403_1
  PROC main()
    TPWrite "a" \Foo:=1;
  ENDPROC
ENDMODULE
