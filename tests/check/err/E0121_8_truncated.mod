MODULE E0121_8
  VAR num n;
  PROC main()
    n := 1;
    n := n + 1;