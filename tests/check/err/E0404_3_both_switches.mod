! expect: E0404 line 8
! both switches of an exclusive pair
MODULE E0404_3
  PROC move(\switch fast | switch slow)
    IF Present(fast) TPWrite "fast";
  ENDPROC
  PROC main()
    move \fast \slow;
  ENDPROC
ENDMODULE
