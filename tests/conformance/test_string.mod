MODULE test_string
    ! TEST works on any value type, here strings (manual 1.2.1).
    PROC command(string cmd)
        TEST cmd
        CASE "start", "go":
            TPWrite "starting";
        CASE "stop":
            TPWrite "stopping";
        DEFAULT:
            TPWrite "unknown " + cmd;
        ENDTEST
    ENDPROC

    PROC main()
        command "go";
        command "stop";
        command "start";
        command "GO";
    ENDPROC
ENDMODULE
