MODULE err_texttab_format
    ! A text table file whose lines are neither `NAME::`, `N:` nor comments cannot be
    ! installed: the program stops (no RAPID error is named for it; docs/semantics.md).
    PROC main()
        VAR iodev f;
        Open "HOME:/bad.eng", f \Write;
        Write f, "bad::";
        Write f, "1:";
        Write f, "a text";
        Write f, "a stray line";
        Close f;
        TPWrite "before";
        TextTabInstall "HOME:/bad.eng";
        TPWrite "after";
    ENDPROC
ENDMODULE
