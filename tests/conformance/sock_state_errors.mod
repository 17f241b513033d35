MODULE sock_state_errors
    ! Each socket instruction used in a state that does not allow it raises the
    ! socket error named for that state; every error is handled and named here.
    ! Port 0 lets the operating system choose a free port (no fixed port).
    VAR socketdev sock;
    VAR socketdev other;
    VAR string text;

    FUNC string name(num e)
        TEST e
        CASE ERR_SOCK_CLOSED:
            RETURN "ERR_SOCK_CLOSED";
        CASE ERR_SOCK_NOT_CONN:
            RETURN "ERR_SOCK_NOT_CONN";
        CASE ERR_SOCK_NOT_BOUND:
            RETURN "ERR_SOCK_NOT_BOUND";
        CASE ERR_SOCK_IS_BOUND:
            RETURN "ERR_SOCK_IS_BOUND";
        CASE ERR_SOCK_IS_CONN:
            RETURN "ERR_SOCK_IS_CONN";
        CASE ERR_SOCK_ADDR_INVALID:
            RETURN "ERR_SOCK_ADDR_INVALID";
        CASE ERR_SOCK_TIMEOUT:
            RETURN "ERR_SOCK_TIMEOUT";
        CASE ERR_SOCK_UNSPEC:
            RETURN "ERR_SOCK_UNSPEC";
        CASE ERR_ARGVALERR:
            RETURN "ERR_ARGVALERR";
        DEFAULT:
            RETURN "another error";
        ENDTEST
    ENDFUNC

    PROC attempt(num k)
        TEST k
        CASE 1:
            ! Never created: the socket is closed.
            SocketSend sock \Str:="x";
        CASE 2:
            SocketReceive sock \Str:=text \Time:=1;
        CASE 3:
            SocketConnect sock, "127.0.0.1", 80;
        CASE 4:
            SocketCreate sock;
            ! Created, not connected.
            SocketSend sock \Str:="x";
        CASE 5:
            SocketReceive sock \Str:=text \Time:=1;
        CASE 6:
            TPWrite "peek " \Num:=SocketPeek(sock);
        CASE 7:
            ! Not bound.
            SocketListen sock;
        CASE 8:
            SocketAccept sock, other \Time:=1;
        CASE 9:
            ! Created twice without SocketClose (uncertain: ERR_SOCK_UNSPEC).
            SocketCreate sock;
        CASE 10:
            ! Addresses are dotted IPv4 numbers; names are not resolved.
            SocketBind sock, "localhost", 0;
        CASE 11:
            SocketBind sock, "127.0.0.256", 0;
        CASE 12:
            SocketConnect sock, "127.0.0.1", 70000;
        CASE 13:
            SocketBind sock, "127.0.0.1", 0;
            TPWrite "bound";
            SocketBind sock, "127.0.0.1", 0;
        CASE 14:
            ! A bound socket is a server socket.
            SocketConnect sock, "127.0.0.1", 80;
        CASE 15:
            SocketListen sock;
            TPWrite "listening";
            ! Nobody connects within 0.1 s.
            SocketAccept sock, other \Time:=0.1;
        CASE 16:
            SocketAccept sock, other \Time:=-1;
        CASE 17:
            SocketClose sock;
            SocketCreate sock \UDP;
            ! A UDP socket never bound has no port to receive on.
            SocketReceiveFrom sock \Str:=text, text, reg1 \Time:=0.1;
        CASE 18:
            ! Not connected: SocketSend needs a connection, UDP too.
            SocketSend sock \Str:="x";
        CASE 19:
            SocketBind sock, "127.0.0.1", 0;
            ! Nothing arrives within 0.1 s.
            SocketReceiveFrom sock \Str:=text, text, reg1 \Time:=0.1;
        CASE 20:
            ! (uncertain: ERR_SOCK_UNSPEC) UDP does not listen.
            SocketListen sock;
        ENDTEST
        TPWrite "step " \Num:=k;
    ERROR
        TPWrite "step " + NumToStr(k, 0) + ": " + name(ERRNO);
        RETURN;
    ENDPROC

    PROC main()
        FOR k FROM 1 TO 20 DO
            attempt k;
        ENDFOR
        SocketClose sock;
        TPWrite "status " \Num:=SocketGetStatus(sock);
    ENDPROC
ENDMODULE
