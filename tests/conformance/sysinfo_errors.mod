MODULE sysinfo_errors
    ! Error paths (uncertain choices, crates/rapid-vm/src/builtins/sysinfo.rs):
    ! GetSysInfo without a switch and a ListNumber that is not 0, 1, 2 ... are
    ! ERR_ARGVALERR.
    PROC no_switch()
        TPWrite GetSysInfo();
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "no switch: ERR_ARGVALERR";
        RETURN;
    ENDPROC

    PROC bad_list_number(num start)
        VAR num n;
        VAR string name;
        n := start;
        IF GetNextOption(n, name) TPWrite "found " + name;
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "list number " + NumToStr(start, 1) + ": ERR_ARGVALERR";
        RETURN;
    ENDPROC

    PROC main()
        no_switch;
        bad_list_number -1;
        bad_list_number 0.5;
        bad_list_number 2;
    ENDPROC
ENDMODULE
