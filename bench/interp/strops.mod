MODULE BenchStrops
  ! Benchmark: the string functions over 2*10^5 short strings built with NumToStr:
  ! StrLen, StrFind (a character and "not found"), StrPart and StrMap on each.

  PROC main()
    VAR string s;
    VAR string t;
    VAR string part;
    VAR num n;
    VAR num p;
    VAR num q;
    VAR num nines := 0;
    VAR num chk := 0;
    FOR i FROM 1 TO 200000 DO
      s := "k" + NumToStr(i MOD 1000, 0) + "x" + NumToStr(i MOD 7, 0) + "abc";
      n := StrLen(s);
      p := StrFind(s, 2, "x");
      part := StrPart(s, 2, p - 2);
      t := StrMap(s, "0123456789abcx", "9876543210ABCY");
      q := StrFind(t, 1, "9");
      IF StrPart(t, p + 1, 1) = "9" THEN
        nines := nines + 1;
      ENDIF
      chk := (chk * 31 + n * 7 + p * 3 + StrLen(part) + q) MOD 65521;
    ENDFOR
    TPWrite "strops nines=" \Num:=nines;
    TPWrite "strops last=" + t;
    TPWrite "strops chk=" \Num:=chk;
  ENDPROC
ENDMODULE
