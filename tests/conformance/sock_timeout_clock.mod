MODULE sock_timeout_clock
    ! A wait on a real socket runs in wall-clock time and the controller clock follows
    ! it (architecture: "virtual time follows wall time" while a task waits on the
    ! outside world), also when the wait ends in ERR_SOCK_TIMEOUT: a clock started
    ! before SocketAccept \Time:=0.3 reads at least 0.3 s in the handler.
    ! Port 0 lets the operating system choose a free port.
    VAR socketdev server;
    VAR socketdev client;
    VAR clock watch;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 0;
        SocketListen server;
        ClkStart watch;
        SocketAccept server, client \Time:=0.3;
        TPWrite "accepted";
    ERROR
        IF ERRNO = ERR_SOCK_TIMEOUT THEN
            ClkStop watch;
            TPWrite "timeout";
            TPWrite "clock followed the wait: " \Bool:=ClkRead(watch) >= 0.3;
            TPWrite "and no more than 5 s: " \Bool:=ClkRead(watch) < 5;
            SocketClose server;
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
