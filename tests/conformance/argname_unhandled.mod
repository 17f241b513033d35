MODULE argname_unhandled
    ! ERR_ARGNAME with no ERROR handler in the call chain stops the program.
    PROC main()
        TPWrite "before";
        show 1 + 2;
        TPWrite "not reached";
    ENDPROC

    PROC show(num par1)
        TPWrite ArgName(par1);
    ENDPROC
ENDMODULE
