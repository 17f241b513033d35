! Not valid UTF-8 (a lone 0xE9 byte in the comment below): decoded as Latin-1, checks clean.
MODULE OK_latin1_fallback
  ! Café crème brûlée ÿ
  VAR num n;
  PROC main()
    n := 1;
  ENDPROC
ENDMODULE
