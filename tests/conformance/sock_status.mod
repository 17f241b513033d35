MODULE sock_status
    ! SocketGetStatus through a socket's life (socketstatus: SOCKET_CREATED 1,
    ! SOCKET_CONNECTED 2, SOCKET_BOUND 3, SOCKET_LISTENING 4, SOCKET_CLOSED 5).
    ! A socketdev never created reports SOCKET_CLOSED, as does one after SocketClose.
    ! Port 0 lets the operating system choose a free port (no fixed port).
    VAR socketdev server;
    VAR socketdev datagram;

    PROC main()
        TPWrite "fresh " \Num:=SocketGetStatus(server);
        SocketCreate server;
        TPWrite "created " \Num:=SocketGetStatus(server);
        SocketBind server, "127.0.0.1", 0;
        TPWrite "bound " \Num:=SocketGetStatus(server);
        SocketListen server;
        TPWrite "listening " \Num:=SocketGetStatus(server);
        IF SocketGetStatus(server) = SOCKET_LISTENING TPWrite "named constant matches";
        SocketClose server;
        TPWrite "closed " \Num:=SocketGetStatus(server);
        ! Closing a closed socket is no error; a closed socket may be created again.
        SocketClose server;
        SocketCreate server;
        TPWrite "created again " \Num:=SocketGetStatus(server);
        SocketClose server;
        ! UDP: created, then bound.
        SocketCreate datagram \UDP;
        TPWrite "udp created " \Num:=SocketGetStatus(datagram);
        SocketBind datagram, "127.0.0.1", 0;
        TPWrite "udp bound " \Num:=SocketGetStatus(datagram);
        ! Nothing has arrived on the bound UDP socket.
        TPWrite "udp peek " \Num:=SocketPeek(datagram);
        SocketClose datagram;
        TPWrite "udp closed " \Num:=SocketGetStatus(datagram);
    ENDPROC
ENDMODULE
