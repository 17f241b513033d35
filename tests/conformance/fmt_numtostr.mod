MODULE fmt_numtostr
    ! FORMAT-DEPENDENT. NumToStr gives exactly Dec decimals, rounded; with
    ! \Exp the mantissa has Dec decimals (semantics 2.3). Halfway cases are
    ! avoided.
    PROC main()
        TPWrite NumToStr(1 / 3, 4);
        TPWrite NumToStr(2 / 3, 2);
        TPWrite NumToStr(7, 3);
        TPWrite NumToStr(1234.5678, 2);
        TPWrite NumToStr(0.38521, 0);
        TPWrite NumToStr(12345, 1 \Exp);
    ENDPROC
ENDMODULE
