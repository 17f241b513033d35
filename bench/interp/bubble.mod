MODULE BenchBubble
  ! Benchmark 4: bubble sort of 1000 nums filled by the LCG x := (75x + 74) MOD 65537.

  CONST num N := 1000;
  VAR num a{1000};

  PROC main()
    VAR num x := 12345;
    VAR num t;
    VAR num chk := 0;
    FOR i FROM 1 TO N DO
      x := (x * 75 + 74) MOD 65537;
      a{i} := x;
    ENDFOR
    FOR i FROM 1 TO N - 1 DO
      FOR j FROM 1 TO N - i DO
        IF a{j} > a{j + 1} THEN
          t := a{j};
          a{j} := a{j + 1};
          a{j + 1} := t;
        ENDIF
      ENDFOR
    ENDFOR
    FOR i FROM 1 TO N DO
      chk := (chk * 31 + a{i}) MOD 65521;
    ENDFOR
    TPWrite "bubble first=" \Num:=a{1};
    TPWrite "bubble last=" \Num:=a{N};
    TPWrite "bubble chk=" \Num:=chk;
  ENDPROC
ENDMODULE
