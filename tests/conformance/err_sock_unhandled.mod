MODULE err_sock_unhandled
    ! A socket error no handler takes stops the program (system error handler).
    VAR socketdev sock;

    PROC main()
        TPWrite "before";
        SocketSend sock \Str:="never created";
        TPWrite "after";
    ENDPROC
ENDMODULE
