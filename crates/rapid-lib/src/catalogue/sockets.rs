//! Catalogue chapter: socket messaging and RAPID Message Queue (manual §1.10, sockets and RMQ parts).

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // --- Socket messaging -------------------------------------------------------------------------
    routine(
        r#"PROC SocketCreate(VAR socketdev Socket \switch UDP)"#,
        "Creates a new TCP (stream) or, with UDP, datagram socket.",
    ),
    routine(
        r#"PROC SocketConnect(VAR socketdev Socket, string Address, num Port \num Time)"#,
        "Connects a client socket to a remote address and port.",
    ),
    routine(
        r#"PROC SocketBind(VAR socketdev Socket, string LocalAddress, num LocalPort)"#,
        "Binds a socket to a local address and port.",
    ),
    routine(
        r#"PROC SocketListen(VAR socketdev Socket)"#,
        "Makes a bound server socket listen for incoming connections.",
    ),
    routine(
        r#"PROC SocketAccept(VAR socketdev Socket, VAR socketdev ClientSocket \VAR string ClientAddress \num Time)"#,
        "Waits for and accepts an incoming connection on a listening socket.",
    ),
    routine(
        r#"PROC SocketSend(VAR socketdev Socket \string Str | VAR rawbytes RawData | byte Data{*} \num NoOfBytes)"#,
        "Sends a string, rawbytes or byte array over a connected socket.",
    ),
    routine(
        r#"PROC SocketSendTo(VAR socketdev Socket, string RemoteAddress, num RemotePort \string Str | VAR rawbytes RawData | byte Data{*} \num NoOfBytes)"#,
        "Sends a datagram to a given remote address and port.",
    ),
    routine(
        r#"PROC SocketReceive(VAR socketdev Socket \VAR string Str | VAR rawbytes RawData | VAR byte Data{*} \num ReadNoOfBytes \VAR num NoRecBytes \num Time)"#,
        "Receives data from a connected socket into a string, rawbytes or byte array.",
    ),
    routine(
        r#"PROC SocketReceiveFrom(VAR socketdev Socket \VAR string Str | VAR rawbytes RawData | VAR byte Data{*} \num ReadNoOfBytes \VAR num NoRecBytes, VAR string RemoteAddress, VAR num RemotePort \num Time)"#,
        "Receives a datagram and reports the sender's address and port.",
    ),
    routine(r#"PROC SocketClose(VAR socketdev Socket)"#, "Closes a socket and releases its resources."),
    routine(r#"FUNC socketstatus SocketGetStatus(VAR socketdev Socket)"#, "Returns the current state of a socket."),
    routine(
        r#"FUNC num SocketPeek(VAR socketdev Socket)"#,
        "Returns how many bytes are waiting to be read on a socket.",
    ),
    // --- RAPID Message Queue ----------------------------------------------------------------------
    routine(
        r#"PROC RMQFindSlot(VAR rmqslot Slot, string Name)"#,
        "Looks up the slot identity of a task queue or SDK client by name.",
    ),
    routine(
        r#"PROC RMQSendMessage(VAR rmqslot Slot, anytype SendData \num UserDef)"#,
        "Sends a value of any type to the queue of the given slot.",
    ),
    routine(
        r#"PROC RMQSendWait(VAR rmqslot Slot, anytype SendData \num UserDef, VAR rmqmessage Message, anytype ReceiveDataType \num Timeout)"#,
        "Sends a message and waits for a reply of the given data type.",
    ),
    routine(
        r#"PROC RMQGetMessage(VAR rmqmessage Message)"#,
        "Takes the first message from the task's queue (used in a TRAP).",
    ),
    routine(
        r#"PROC RMQGetMsgData(VAR rmqmessage Message, VAR anytype Data)"#,
        "Copies the data part of a received message into a variable of its type.",
    ),
    routine(
        r#"PROC RMQGetMsgHeader(VAR rmqmessage Message \VAR rmqheader Header \VAR rmqslot SenderId \VAR num UserDef)"#,
        "Copies header, sender identity and user data out of a received message.",
    ),
    routine(
        r#"PROC RMQReadWait(VAR rmqmessage Message \num TimeOut)"#,
        "Waits (synchronous mode) until a message arrives in the task's queue.",
    ),
    routine(r#"PROC RMQEmptyQueue()"#, "Discards all messages in the queue of the executing task."),
    routine(
        r#"FUNC string RMQGetSlotName(VAR rmqslot Slot)"#,
        "Returns the name of the queue or client behind a slot identity.",
    ),
];
