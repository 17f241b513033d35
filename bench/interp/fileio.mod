MODULE BenchFileio
  ! Benchmark: 10^5 lines written with Write (text with a number, then a number alone)
  ! to HOME:, then read back with ReadStr and ReadNum.

  PROC main()
    VAR iodev f;
    VAR string s;
    VAR num n;
    VAR num lines := 0;
    VAR num chk := 0;
    Open "HOME:/bench_fileio.txt", f \Write;
    FOR i FROM 1 TO 50000 DO
      Write f, "row " \Num:=i;
      Write f, "" \Num:=(i * 7) MOD 9973;
    ENDFOR
    Close f;
    Open "HOME:/bench_fileio.txt", f \Read;
    FOR i FROM 1 TO 50000 DO
      s := ReadStr(f);
      n := ReadNum(f);
      chk := (chk * 31 + StrLen(s) + n) MOD 65521;
      lines := lines + 2;
    ENDFOR
    s := ReadStr(f);
    Close f;
    TPWrite "fileio lines=" \Num:=lines;
    TPWrite "fileio chk=" \Num:=chk;
    TPWrite "fileio end=" + s;
  ENDPROC
ENDMODULE
