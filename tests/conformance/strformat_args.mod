MODULE strformat_args
    ! StrFormat fills {1}..{10} with \Arg1..\Arg10 (RW 6.11; the form used by
    ! abb-motion-program-exec). A placeholder without its argument stays as written
    ! (uncertain, see crates/rapid-vm/src/builtins/strformat.rs).
    PROC too_long()
        VAR string s;
        s := StrFormat("{1}{1}{1}" \Arg1:="abcdefghijklmnopqrstuvwxyz1234");
        TPWrite "no error";
    ERROR
        IF ERRNO = ERR_STRTOOLNG TPWrite "90 characters: ERR_STRTOOLNG";
        RETURN;
    ENDPROC

    PROC main()
        TPWrite StrFormat("motion_program_p{1}.bin" \Arg1:=NumToStr(3, 0));
        TPWrite StrFormat("{2} before {1}" \Arg1:="one" \Arg2:="two");
        TPWrite StrFormat("{1}{1}" \Arg1:="ab");
        TPWrite StrFormat("no placeholders");
        TPWrite StrFormat("{1} and {3}" \Arg1:="x");
        TPWrite StrFormat("{10}!" \Arg10:="ten");
        TPWrite StrFormat("{1}" \Arg1:="");
        too_long;
    ENDPROC
ENDMODULE
