MODULE BenchStrings
  ! Benchmark 3: 10^6 string concatenations. The string grows by 2 or 3 characters at a
  ! time and is reset once longer than 76 characters, so it never exceeds 80 (RAPID's limit).

  PROC main()
    VAR string s := "";
    VAR num n;
    VAR num resets := 0;
    VAR num chk := 0;
    FOR i FROM 1 TO 1000 DO
      FOR j FROM 1 TO 1000 DO
        s := s + NumToStr((i + j) MOD 97, 0) + ";";
        n := StrLen(s);
        IF n > 76 THEN
          chk := (chk * 31 + n) MOD 65521;
          resets := resets + 1;
          s := "";
        ENDIF
      ENDFOR
    ENDFOR
    chk := (chk * 31 + StrLen(s)) MOD 65521;
    TPWrite "strings resets=" \Num:=resets;
    TPWrite "strings chk=" \Num:=chk;
  ENDPROC
ENDMODULE
