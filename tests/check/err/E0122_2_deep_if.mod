! expect: E0122 line 262
! 1000 nested IF blocks, one per line: the 257th crosses the 256-level statement limit
MODULE E0122_2
  VAR bool b;
  PROC main()
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    IF b THEN
    b := FALSE;
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
    ENDIF
  ENDPROC
ENDMODULE
