//! Socket Messaging (§1.10): SocketCreate, SocketConnect, SocketBind, SocketListen,
//! SocketAccept, SocketSend, SocketSendTo, SocketReceive, SocketReceiveFrom,
//! SocketClose, SocketGetStatus, SocketPeek, on the TCP and UDP sockets of the task's
//! world (`rapid_vm::ext::Network`: std::net in the controller's std world), an extension
//! of the interpreter ([`EXTENSION`]).
//!
//! A `socketdev` holds `OpaqueState::Handle(n)`, the number of its entry in the task's
//! [`SocketState`] (table.rs); a fresh or closed one holds nothing and reports
//! SOCKET_CLOSED. Argument data is converted in payload.rs.
//!
//! Time. A wait on a real socket runs in wall-clock time (the world's clock), and the controller's virtual
//! clock must not skip past it. The VM is single-threaded, so a waiting built-in
//! blocks, with an OS timeout that never goes past the RAPID `\Time` (60 s when not
//! given; WAIT_MAX is honoured as about 97 days), and then reports the wall time it
//! spent through `ctx.waited`: the VM advances the virtual clock by exactly that much,
//! also when the wait ends in an error (ERR_SOCK_TIMEOUT), and nobody sleeps it again
//! (not even `rapid run --realtime`).
//!
//! Cooperatively (`SocketState::set_cooperative`, as `rapid run` and the controller set
//! it for every task, so that other tasks and traps run while one waits), SocketAccept, SocketReceive and SocketReceiveFrom do
//! not block: each try makes what progress it can without waiting (table.rs's `poll_*`
//! steps, reached with a deadline of now), and while nothing has come the statement is
//! run again `POLL_PERIOD` later (`StopKind::Repeat`, as WaitDI waits), the other tasks
//! running meanwhile. `\Time` then counts controller time from the first try, and the
//! controller paces its clock in wall-clock time while a task waits so
//! (`SocketState::is_polling`), so the peer has the time the program gives it.
//! SocketConnect and SocketSend still block (briefly, unless the peer is unreachable
//! or reads nothing).
// uncertain: interrupts may run a trap while a socket wait is under way in a system, as
// during WaitDI; whether the controller serves traps during SocketReceive is not
// documented.

mod payload;
mod table;

use std::net::{Ipv4Addr, SocketAddr, SocketAddrV4};
use std::rc::Rc;
use std::str::FromStr;
use std::time::Duration;

use rapid_vm::ext::{
    native, present, wait_again, wait_over, wait_started, Clock, Ctx, Err, Extension, Family, Network, Opaque,
    OpaqueState, RapidError, Resources, TaskHooks, TaskState, Value,
};
pub use table::{SocketState, Status, SERVICE_PORT_ADDR};

type Res = Result<Option<Value>, RapidError>;

/// The `\Time` of Connect, Accept and the receives when none is given (manual: 60 s).
const DEFAULT_TIME: f64 = 60.0;

/// Controller seconds between two tries of a socket wait in cooperative mode: the
/// controller's 4 ms period.
const POLL_PERIOD: f64 = 0.004;

static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("SocketCreate", socket_create),
        native("SocketConnect", socket_connect),
        native("SocketBind", socket_bind),
        native("SocketListen", socket_listen),
        native("SocketAccept", socket_accept),
        native("SocketSend", socket_send),
        native("SocketSendTo", socket_send_to),
        native("SocketReceive", socket_receive),
        native("SocketReceiveFrom", socket_receive_from),
        native("SocketClose", socket_close),
        native("SocketGetStatus", socket_get_status),
        native("SocketPeek", socket_peek),
    ],
};

/// The socket built-ins, their per-task table, and the world's network handed to it.
pub static EXTENSION: Extension =
    Extension { name: "sockets", families: &[&FAMILY], hooks: Some(&SocketHooks), init: Some(init) };

fn init(resources: &mut Resources) {
    resources.extensions.insert(SocketState::default());
}

struct SocketHooks;

impl TaskHooks for SocketHooks {
    fn world_given(&self, resources: &mut Resources, net: &mut Option<Box<dyn Network>>, clock: &Rc<dyn Clock>) {
        if let Some(net) = net.take() {
            resources.extensions.get_or_default::<SocketState>().set_network(net, clock.clone());
        }
    }
}

impl TaskState for SocketState {
    /// Closes every socket (end of program, PP to Main).
    fn close_all(&mut self) {
        SocketState::close_all(self);
    }
}

/// The task's sockets, if it was made with this extension.
pub fn of(resources: &Resources) -> Option<&SocketState> {
    resources.extensions.get::<SocketState>()
}

/// The task's sockets, to change (put in if the task had none).
pub fn of_mut(resources: &mut Resources) -> &mut SocketState {
    resources.extensions.get_or_default::<SocketState>()
}

/// The task's socket table.
fn sockets<'a>(ctx: &'a mut Ctx<'_>) -> &'a mut SocketState {
    of_mut(ctx.resources)
}

/// `SocketCreate Socket [\UDP]`: a new TCP (stream) or UDP (datagram) socket.
fn socket_create(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (opaque, handle) = socket_arg(ctx, &args[0])?;
    // uncertain: the manual says the socket must not be in use; the error it raises
    // then is not documented (ERR_SOCK_UNSPEC here). A socket whose connection broke
    // may be created again.
    if sockets(ctx).is_offline() {
        return Err(ctx.error(Err::SockUnspec, "this controller has no network (sockets are switched off)"));
    }
    if sockets(ctx).in_use(handle) {
        return Err(ctx.error(Err::SockUnspec, "the socket is already created (SocketClose it first)"));
    }
    sockets(ctx).close(handle);
    let new = sockets(ctx).create(present(args.get(1))).map_err(|f| fault(ctx, f))?;
    set_handle(ctx, &args[0], opaque, Some(new))
}

/// `SocketConnect Socket Address Port [\Time]`: connects to a remote computer.
fn socket_connect(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *CONNECT;
    let (_, handle) = socket_arg(ctx, &args[at.socket])?;
    let to = remote_addr(ctx, &args[at.address], &args[at.port])?;
    let timeout = time_arg(ctx, args.get(at.time))?;
    let started = sockets(ctx).now();
    let res = sockets(ctx).connect(handle, to, deadline(started, timeout));
    finish_wait(ctx, started, res)?;
    Ok(None)
}

/// `SocketBind Socket LocalAddress LocalPort`: binds to a local address and port
/// (port 0: one the OS chooses). The controller's own addresses bind the loopback.
fn socket_bind(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, handle) = socket_arg(ctx, &args[0])?;
    let at = *BIND;
    let asked = ip_arg(ctx, &args[at.address])?;
    let port = port_arg(ctx, &args[at.port], true)?;
    let (ip, first) = sockets(ctx).bind_addr(asked);
    if first {
        ctx.host.note(&format!(
            "SocketBind to {asked}, an address of the controller itself, binds {ip} (the virtual controller's \
             address; clients connect to {ip})"
        ));
    }
    sockets(ctx).bind(handle, SocketAddrV4::new(ip, port)).map_err(|f| fault(ctx, f))?;
    Ok(None)
}

/// `SocketListen Socket`: a bound TCP socket starts taking connections.
fn socket_listen(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, handle) = socket_arg(ctx, &args[0])?;
    sockets(ctx).listen(handle).map_err(|f| fault(ctx, f))?;
    Ok(None)
}

/// `SocketAccept Socket ClientSocket [\ClientAddress] [\Time]`: waits for a client;
/// ClientSocket becomes the connection, ClientAddress the client's IP address.
fn socket_accept(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ACCEPT;
    let (_, handle) = socket_arg(ctx, &args[at.socket])?;
    let (client, client_handle) = socket_arg(ctx, &args[at.client])?;
    let timeout = time_arg(ctx, args.get(at.time))?;
    let Some((new, ip)) = wait_for(ctx, timeout, |sockets, deadline| sockets.accept(handle, deadline))? else {
        return Ok(None);
    };
    // uncertain: a ClientSocket still in use is replaced (its connection closed); the
    // manual documents no error for it.
    sockets(ctx).close(client_handle);
    set_handle(ctx, &args[at.client], client, Some(new))?;
    if present(args.get(at.client_address)) {
        ctx.store(&args[at.client_address], Value::Str(ip.to_string().into()))?;
    }
    Ok(None)
}

rapid_vm::ext::layout! {
    static BIND: BindArgs = "SocketBind" { address: "LocalAddress", port: "LocalPort" }
    static CONNECT: ConnectArgs = "SocketConnect" { socket: "Socket", address: "Address", port: "Port", time: "Time" }
    static ACCEPT: AcceptArgs = "SocketAccept" {
        socket: "Socket", client: "ClientSocket", client_address: "ClientAddress", time: "Time",
    }
    static SEND: SendArgs = "SocketSend" { socket: "Socket", str: "Str", no_of_bytes: "NoOfBytes" }
    static SEND_TO: SendToArgs = "SocketSendTo" {
        socket: "Socket", address: "RemoteAddress", port: "RemotePort", str: "Str", no_of_bytes: "NoOfBytes",
    }
    static RECEIVE: ReceiveArgs = "SocketReceive" {
        socket: "Socket", str: "Str", read_no_of_bytes: "ReadNoOfBytes", no_rec_bytes: "NoRecBytes", time: "Time",
    }
    static RECEIVE_FROM: ReceiveFromArgs = "SocketReceiveFrom" {
        socket: "Socket", str: "Str", read_no_of_bytes: "ReadNoOfBytes", no_rec_bytes: "NoRecBytes",
        address: "RemoteAddress", port: "RemotePort", time: "Time",
    }
}

/// `SocketSend Socket [\Str] | [\RawData] | [\Data] [\NoOfBytes]`.
fn socket_send(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SEND;
    let (_, handle) = socket_arg(ctx, &args[at.socket])?;
    // The payload is one of \Str, \RawData, \Data, declared in that order.
    let slot = payload::chosen(ctx, args, at.str)?;
    let no_of_bytes = ctx.opt_num(args.get(at.no_of_bytes))?;
    let bytes = payload::bytes_to_send(ctx, args, slot, no_of_bytes)?;
    let started = sockets(ctx).now();
    // uncertain: the manual gives no send timeout; a peer that reads nothing may hold
    // a send for at most the default 60 s before ERR_SOCK_TIMEOUT.
    let res = sockets(ctx).send(handle, &bytes, deadline(started, Duration::from_secs(60)));
    finish_wait(ctx, started, res)?;
    Ok(None)
}

/// `SocketSendTo Socket RemoteAddress RemotePort [\Str] | [\RawData] | [\Data]
/// [\NoOfBytes]`: one datagram.
fn socket_send_to(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SEND_TO;
    let (_, handle) = socket_arg(ctx, &args[at.socket])?;
    let to = remote_addr(ctx, &args[at.address], &args[at.port])?;
    let slot = payload::chosen(ctx, args, at.str)?;
    let no_of_bytes = ctx.opt_num(args.get(at.no_of_bytes))?;
    let bytes = payload::bytes_to_send(ctx, args, slot, no_of_bytes)?;
    sockets(ctx).send_to(handle, &bytes, to).map_err(|f| fault(ctx, f))?;
    Ok(None)
}

/// `SocketReceive Socket [\Str] | [\RawData] | [\Data] [\ReadNoOfBytes] [\NoRecBytes]
/// [\Time]`: waits for data; without \ReadNoOfBytes takes what has arrived (at least
/// one byte, at most what the data holds), with it waits for exactly that many.
fn socket_receive(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *RECEIVE;
    let (_, handle) = socket_arg(ctx, &args[at.socket])?;
    let slot = payload::chosen(ctx, args, at.str)?;
    let capacity = payload::capacity(ctx, args, slot)?;
    let want = match ctx.opt_num(args.get(at.read_no_of_bytes))? {
        Some(n) => {
            let n = payload::read_count(ctx, n, capacity)?;
            table::Want { min: n, max: n }
        }
        None => table::Want { min: 1, max: capacity },
    };
    let timeout = time_arg(ctx, args.get(at.time))?;
    let Some(bytes) = wait_for(ctx, timeout, |sockets, deadline| sockets.receive(handle, want, deadline))? else {
        return Ok(None);
    };
    payload::store_received(ctx, args, slot, &bytes)?;
    if present(args.get(at.no_rec_bytes)) {
        ctx.store(&args[at.no_rec_bytes], Value::Num(bytes.len() as f32))?;
    }
    Ok(None)
}

/// `SocketReceiveFrom Socket [\Str] | [\RawData] | [\Data] [\ReadNoOfBytes]
/// [\NoRecBytes] RemoteAddress RemotePort [\Time]`: the next datagram and its sender.
fn socket_receive_from(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *RECEIVE_FROM;
    let (_, handle) = socket_arg(ctx, &args[at.socket])?;
    let slot = payload::chosen(ctx, args, at.str)?;
    let capacity = payload::capacity(ctx, args, slot)?;
    // uncertain: for a datagram, \ReadNoOfBytes is read as the most bytes to keep.
    let max = match ctx.opt_num(args.get(at.read_no_of_bytes))? {
        Some(n) => payload::read_count(ctx, n, capacity)?,
        None => capacity,
    };
    let timeout = time_arg(ctx, args.get(at.time))?;
    let wait = wait_for(ctx, timeout, |sockets, deadline| sockets.receive_from(handle, max, deadline))?;
    let Some((bytes, from)) = wait else { return Ok(None) };
    payload::store_received(ctx, args, slot, &bytes)?;
    if present(args.get(at.no_rec_bytes)) {
        ctx.store(&args[at.no_rec_bytes], Value::Num(bytes.len() as f32))?;
    }
    let (ip, port) = match from {
        SocketAddr::V4(v4) => (*v4.ip(), v4.port()),
        SocketAddr::V6(v6) => (v6.ip().to_ipv4_mapped().unwrap_or(Ipv4Addr::UNSPECIFIED), v6.port()),
    };
    ctx.store(&args[at.address], Value::Str(ip.to_string().into()))?;
    ctx.store(&args[at.port], Value::Num(f32::from(port)))?;
    Ok(None)
}

/// `SocketClose Socket`: closes the socket; closing one not in use is no error.
fn socket_close(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (opaque, handle) = socket_arg(ctx, &args[0])?;
    sockets(ctx).close(handle);
    set_handle(ctx, &args[0], opaque, None)
}

/// `SocketGetStatus(Socket)`: SOCKET_CREATED, _CONNECTED, _BOUND, _LISTENING or
/// _CLOSED (also for a socket never created).
// uncertain: a socket whose peer closed still reports SOCKET_CONNECTED until a send or
// receive finds out (the controller keeps the state its instructions set).
fn socket_get_status(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, handle) = socket_arg(ctx, &args[0])?;
    let status = sockets(ctx).status(handle);
    Ok(Some(Value::Num(status as u8 as f32)))
}

/// `SocketPeek(Socket)`: how many bytes have arrived and not been received yet.
fn socket_peek(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, handle) = socket_arg(ctx, &args[0])?;
    let n = sockets(ctx).peek(handle).map_err(|f| fault(ctx, f))?;
    Ok(Some(Value::Num(n as f32)))
}

// ---- helpers --------------------------------------------------------------------------

/// The socketdev an argument names and the handle it holds (none when fresh/closed).
fn socket_arg(ctx: &Ctx<'_>, arg: &Value) -> Result<(Opaque, Option<u32>), RapidError> {
    ctx.handle_arg(arg, "a socketdev")
}

fn set_handle(ctx: &mut Ctx<'_>, arg: &Value, mut opaque: Opaque, handle: Option<u32>) -> Res {
    opaque.state = handle.map_or(OpaqueState::None, OpaqueState::Handle);
    ctx.store(arg, Value::Opaque(Box::new(opaque)))?;
    Ok(None)
}

/// Runs socket operation `op` (given its deadline) for at most `timeout`. A task running
/// alone blocks in it. In cooperative mode it is tried without waiting: `None` while
/// nothing has come and time is left (the statement runs again a poll later), else its
/// outcome, ERR_SOCK_TIMEOUT once `timeout` of controller time has passed.
fn wait_for<T>(
    ctx: &mut Ctx<'_>,
    timeout: Duration,
    op: impl FnOnce(&mut SocketState, table::Deadline) -> Result<T, table::Fault>,
) -> Result<Option<T>, RapidError> {
    if !sockets(ctx).is_cooperative() {
        let started = sockets(ctx).now();
        let res = op(sockets(ctx), deadline(started, timeout));
        return finish_wait(ctx, started, res).map(Some);
    }
    let started = wait_started(ctx);
    let until = started + timeout.as_secs_f64();
    let now = sockets(ctx).now();
    match op(sockets(ctx), now) {
        Err((Err::SockTimeout, _)) if ctx.time < until => {
            sockets(ctx).set_polling(true);
            let next = ctx.time + POLL_PERIOD;
            wait_again(ctx, started, Some(until), Some(next));
            Ok(None)
        }
        res => {
            wait_over(ctx);
            sockets(ctx).set_polling(false);
            res.map(Some).map_err(|f| fault(ctx, f))
        }
    }
}

/// Reports the wall time a socket operation took as a wait of the controller clock,
/// and turns its fault into the RAPID error.
fn finish_wait<T>(ctx: &mut Ctx<'_>, started: table::Deadline, res: Result<T, table::Fault>) -> Result<T, RapidError> {
    ctx.waited = sockets(ctx).now().saturating_sub(started).as_secs_f64();
    res.map_err(|f| fault(ctx, f))
}

fn fault(ctx: &Ctx<'_>, (err, message): table::Fault) -> RapidError {
    ctx.error(err, message)
}

/// `\Time` in seconds (60 when absent); 0 means do not wait.
// uncertain: the manual does not say what a negative \Time raises (ERR_ARGVALERR).
fn time_arg(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<Duration, RapidError> {
    let seconds = ctx.opt_num(arg)?.unwrap_or(DEFAULT_TIME);
    Duration::try_from_secs_f64(seconds)
        .map_err(|_| ctx.error(Err::ArgValue, format!("\\Time:={seconds} is not a time of 0 or more seconds")))
}

/// The instant `timeout` after `started` (far in the future if that overflows).
fn deadline(started: table::Deadline, timeout: Duration) -> table::Deadline {
    started.checked_add(timeout).unwrap_or_else(|| started + Duration::from_secs(86_400 * 365))
}

/// An IPv4 address in dotted form ("192.168.125.1"); names are not resolved.
fn ip_arg(ctx: &Ctx<'_>, arg: &Value) -> Result<Ipv4Addr, RapidError> {
    let text = ctx.string(arg)?;
    Ipv4Addr::from_str(&text)
        .map_err(|_| ctx.error(Err::SockAddrInvalid, format!("`{text}` is not an IP address like 192.168.125.1")))
}

/// A port number 0..65535 (0 only where the OS may choose one: SocketBind).
// uncertain: the error for a port out of range is not documented (ERR_SOCK_ADDR_INVALID).
fn port_arg(ctx: &Ctx<'_>, arg: &Value, zero_ok: bool) -> Result<u16, RapidError> {
    let port = ctx.num(arg)?;
    let lowest = if zero_ok { 0.0 } else { 1.0 };
    if port.fract() != 0.0 || !(lowest..=65_535.0).contains(&port) {
        return Err(ctx.error(Err::SockAddrInvalid, format!("{port} is not a port number")));
    }
    Ok(port as u16)
}

/// The remote address and port of SocketConnect / SocketSendTo.
fn remote_addr(ctx: &Ctx<'_>, address: &Value, port: &Value) -> Result<SocketAddrV4, RapidError> {
    Ok(SocketAddrV4::new(ip_arg(ctx, address)?, port_arg(ctx, port, false)?))
}
