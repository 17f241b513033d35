MODULE texttab_basic
    ! The program writes a text table file on HOME: and installs it. Format (ABB's text
    ! resource files, docs/semantics.md): `NAME::` names the table, each `N:` line gives
    ! the index of the text on the next line, `#` lines are comments. TextTabFreeToUse
    ! is TRUE until the name is installed; names ignore letter case; TextGet fills
    ! {1} and {2} from \Arg1 and \Arg2 and leaves them when the arguments are absent.
    ! Installing the same table again keeps the one table (its number stays).
    PROC main()
        VAR iodev f;
        VAR num tab;
        TPWrite "free=" \Bool:=TextTabFreeToUse("greetings");
        Open "HOME:/texts.eng", f \Write;
        Write f, "# texts for the operator";
        Write f, "greetings::";
        Write f, "1:";
        Write f, "Hello operator";
        Write f, "# the second text";
        Write f, "2:";
        Write f, "Part {1} of {2} done";
        Write f, "10:";
        Write f, "";
        Close f;
        TextTabInstall "HOME:/texts.eng";
        TPWrite "free=" \Bool:=TextTabFreeToUse("GREETINGS");
        tab := TextTabGet("greetings");
        TPWrite TextGet(tab, 1);
        TPWrite TextGet(tab, 2 \Arg1:="3" \Arg2:="5");
        TPWrite TextGet(tab, 2);
        TPWrite "[" + TextGet(tab, 10) + "]";
        TextTabInstall "HOME:/texts.eng";
        TPWrite "same=" \Bool:=(TextTabGet("Greetings") = tab);
    ENDPROC
ENDMODULE
