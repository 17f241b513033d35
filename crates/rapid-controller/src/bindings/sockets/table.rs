//! The task's socket table: one entry per created `socketdev`, holding the endpoint
//! the world's network made (`rapid_vm::ext::Network`) and the state SocketGetStatus
//! reports. Every operation that can wait takes a deadline on the world's clock and
//! never blocks past it.
//!
//! Waiting is split in two so that a scheduler can later poll instead of block: the
//! `poll_*` functions make whatever progress is possible without waiting and say
//! whether the operation is complete; the public operations loop over them, blocking
//! (with an OS timeout, or a short sleep where std offers no timed call) until the
//! deadline.

use std::io;
use std::net::{Ipv4Addr, SocketAddr, SocketAddrV4};
use std::rc::Rc;
use std::time::Duration;

use rustc_hash::FxHashMap;

use rapid_vm::ext::{Clock, Err, Network, NoNetwork, StoppedClock, TcpConn, TcpListen, UdpConn};

/// A moment on the world's monotonic clock ([`Clock::elapsed`]).
pub(super) type Deadline = Duration;

/// A RAPID error to raise: its name and a message.
pub(super) type Fault = (Err, String);

/// How many sockets a task may hold open at once.
// uncertain: the manual's SocketCreate limitations name 32 sockets; the error for
// going past it is not documented (ERR_SOCK_UNSPEC here).
pub(super) const MAX_SOCKETS: usize = rapid_limits::SOCKETS;

/// Bytes read ahead of the program but not yet received by it, at most.
const PENDING_CAP: usize = 64 * 1024;

/// The longest sleep between two polls where std has no timed call (accept).
const POLL_STEP: Duration = Duration::from_millis(5);

/// `socketstatus` values (the SOCKET_* constants of the catalogue).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    Created = 1,
    Connected = 2,
    Bound = 3,
    Listening = 4,
    Closed = 5,
}

/// How much a receive wants: at least `min` bytes (waiting for them), at most `max`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Want {
    pub min: usize,
    pub max: usize,
}

/// A connected TCP stream and the bytes read from it ahead of the program.
struct Stream {
    tcp: Box<dyn TcpConn>,
    pending: Vec<u8>,
    /// The peer closed its side: no byte will follow `pending`.
    eof: bool,
}

/// One socket, in the state its RAPID instructions have put it.
enum Endpoint {
    /// SocketCreate (TCP): no OS socket until SocketConnect or SocketBind.
    TcpNew,
    /// SocketBind (TCP); `listening` after SocketListen.
    // uncertain: std binds and listens in one call, so a client connecting between
    // SocketBind and SocketListen is queued instead of refused.
    TcpBound {
        listener: Box<dyn TcpListen>,
        listening: bool,
    },
    TcpConnected(Stream),
    /// SocketCreate \UDP: the OS socket is made by SocketBind, SocketConnect or the
    /// first SocketSendTo (which binds to any free port, as sendto does).
    UdpNew,
    Udp {
        socket: Box<dyn UdpConn>,
        bound: bool,
        connected: bool,
    },
    /// The connection broke or the peer closed it: every use raises ERR_SOCK_CLOSED
    /// until SocketClose.
    Broken,
}

/// Open sockets of the task, by the handle their `socketdev` holds.
pub struct SocketState {
    /// The world's network and clock (none until the embedder gives a world).
    net: Box<dyn Network>,
    clock: Rc<dyn Clock>,
    entries: FxHashMap<u32, Endpoint>,
    /// Handles are never reused, so a stale `socketdev` never reaches a new socket.
    next_handle: u32,
    /// No network for this task (fuzzing, sandboxed hosts): SocketCreate fails.
    offline: bool,
    /// The task runs beside others: a socket wait polls and gives way (mod.rs).
    cooperative: bool,
    /// A socket wait of the task is under way in cooperative mode.
    polling: bool,
    /// The controller's own addresses beside its service port's (`--controller-ip`).
    controller_addrs: Vec<Ipv4Addr>,
    /// The controller addresses a bind was moved to the loopback for, each told once.
    mapped: Vec<Ipv4Addr>,
}

/// The address of the controller's service port (RobotWare's fixed 192.168.125.1).
pub const SERVICE_PORT_ADDR: Ipv4Addr = Ipv4Addr::new(192, 168, 125, 1);

impl Default for SocketState {
    fn default() -> SocketState {
        SocketState {
            net: Box::new(NoNetwork),
            clock: Rc::new(StoppedClock::default()),
            entries: FxHashMap::default(),
            next_handle: 0,
            offline: false,
            cooperative: false,
            polling: false,
            controller_addrs: Vec::new(),
            mapped: Vec::new(),
        }
    }
}

impl SocketState {
    /// The network the sockets reach and the clock their waits run on.
    pub fn set_network(&mut self, net: Box<dyn Network>, clock: Rc<dyn Clock>) {
        self.net = net;
        self.clock = clock;
    }

    /// Now on the world's monotonic clock.
    pub(super) fn now(&self) -> Deadline {
        self.clock.elapsed()
    }

    /// Takes the network away from (or gives it back to) the task.
    pub fn set_offline(&mut self, offline: bool) {
        self.offline = offline;
    }

    /// Whether the task has no network: taken away, or its world has none.
    pub fn is_offline(&self) -> bool {
        self.offline || self.net.is_closed()
    }

    /// One more address of the controller's own (its LAN port's, as the system was
    /// given it): a SocketBind to it binds the loopback.
    pub fn add_controller_addr(&mut self, ip: Ipv4Addr) {
        if !self.controller_addrs.contains(&ip) {
            self.controller_addrs.push(ip);
        }
    }

    /// Where a SocketBind to `ip` binds: a virtual controller has none of the real
    /// one's network ports, so its own addresses (the service port's, and those given
    /// with [`SocketState::add_controller_addr`]) are mapped to the loopback, as a
    /// virtual controller in RobotStudio maps them. The second answer is true the first
    /// time an address is mapped, when the run says so.
    pub(super) fn bind_addr(&mut self, ip: Ipv4Addr) -> (Ipv4Addr, bool) {
        if ip != SERVICE_PORT_ADDR && !self.controller_addrs.contains(&ip) {
            return (ip, false);
        }
        let first = !self.mapped.contains(&ip);
        if first {
            self.mapped.push(ip);
        }
        (Ipv4Addr::LOCALHOST, first)
    }

    /// Makes the task's socket waits polls that give way to other tasks (a task of a
    /// system) instead of blocking the process (a task running alone).
    pub fn set_cooperative(&mut self, cooperative: bool) {
        self.cooperative = cooperative;
    }

    pub(super) fn is_cooperative(&self) -> bool {
        self.cooperative
    }

    /// Whether the task holds a socket that talks to the outside world: connected,
    /// listening, or a bound UDP socket.
    pub fn is_open(&self) -> bool {
        self.entries.values().any(|e| !matches!(e, Endpoint::TcpNew | Endpoint::UdpNew | Endpoint::Broken))
    }

    /// Whether the task waits on a socket now (cooperative mode): what it waits for
    /// comes from outside, in wall-clock time.
    pub fn is_polling(&self) -> bool {
        self.polling
    }

    pub(super) fn set_polling(&mut self, polling: bool) {
        self.polling = polling;
    }

    /// Closes every socket.
    pub fn close_all(&mut self) {
        self.entries.clear();
    }

    /// The local addresses of the TCP sockets bound by SocketBind and of bound UDP
    /// sockets, in handle order: how a test learns the port the OS chose for port 0.
    pub fn bound_addrs(&self) -> Vec<SocketAddr> {
        let mut handles: Vec<&u32> = self.entries.keys().collect();
        handles.sort();
        handles
            .into_iter()
            .filter_map(|h| match &self.entries[h] {
                Endpoint::TcpBound { listener, .. } => listener.local_addr().ok(),
                Endpoint::Udp { socket, bound: true, .. } => socket.local_addr().ok(),
                _ => None,
            })
            .collect()
    }

    /// The state of the socket behind `handle` (SOCKET_CLOSED for a socket never
    /// created or already closed).
    pub fn status(&self, handle: Option<u32>) -> Status {
        match handle.and_then(|h| self.entries.get(&h)) {
            None | Some(Endpoint::Broken) => Status::Closed,
            Some(Endpoint::TcpNew | Endpoint::UdpNew) => Status::Created,
            Some(Endpoint::TcpBound { listening: false, .. }) => Status::Bound,
            Some(Endpoint::TcpBound { listening: true, .. }) => Status::Listening,
            Some(Endpoint::TcpConnected(_)) | Some(Endpoint::Udp { connected: true, .. }) => Status::Connected,
            Some(Endpoint::Udp { bound: true, .. }) => Status::Bound,
            Some(Endpoint::Udp { .. }) => Status::Created,
        }
    }

    /// Whether `handle` names a socket that is in use (created and not closed).
    pub(super) fn in_use(&self, handle: Option<u32>) -> bool {
        handle.and_then(|h| self.entries.get(&h)).is_some_and(|e| !matches!(e, Endpoint::Broken))
    }

    /// SocketCreate: a new socket; its handle.
    pub(super) fn create(&mut self, udp: bool) -> Result<u32, Fault> {
        if self.entries.len() >= MAX_SOCKETS {
            return Err((Err::SockUnspec, format!("a task can hold at most {MAX_SOCKETS} sockets")));
        }
        let handle = self.next_handle;
        self.next_handle = self.next_handle.wrapping_add(1);
        self.entries.insert(handle, if udp { Endpoint::UdpNew } else { Endpoint::TcpNew });
        Ok(handle)
    }

    /// SocketClose: releases the socket (nothing to do for one not in use).
    pub(super) fn close(&mut self, handle: Option<u32>) {
        if let Some(h) = handle {
            self.entries.remove(&h);
        }
    }

    /// The entry of a socket in use; ERR_SOCK_CLOSED otherwise.
    fn entry(&mut self, handle: Option<u32>) -> Result<&mut Endpoint, Fault> {
        entry_of(&mut self.entries, handle)
    }

    /// SocketConnect.
    pub(super) fn connect(&mut self, handle: Option<u32>, to: SocketAddrV4, deadline: Deadline) -> Result<(), Fault> {
        let (net, clock) = (&self.net, &self.clock);
        let entry = entry_of(&mut self.entries, handle)?;
        match entry {
            Endpoint::TcpNew => {
                let timeout = remaining(&**clock, deadline).max(Duration::from_millis(1));
                let tcp = net.tcp_connect(to, timeout).map_err(|e| io_fault(&e))?;
                *entry = Endpoint::TcpConnected(Stream { tcp, pending: Vec::new(), eof: false });
                Ok(())
            }
            // uncertain: the manual does not say whether a UDP socket may connect; BSD
            // sockets allow it (it fixes the peer of SocketSend / SocketReceive).
            Endpoint::UdpNew => {
                let mut socket = net.udp_bind(any_port()).map_err(|e| io_fault(&e))?;
                socket.connect(to).map_err(|e| io_fault(&e))?;
                *entry = Endpoint::Udp { socket, bound: false, connected: true };
                Ok(())
            }
            Endpoint::Udp { socket, connected, .. } => {
                socket.connect(to).map_err(|e| io_fault(&e))?;
                *connected = true;
                Ok(())
            }
            Endpoint::TcpConnected(_) => Err(is_connected()),
            // uncertain: std cannot connect from a bound TCP socket; BSD would allow it.
            Endpoint::TcpBound { .. } => Err((Err::SockIsBound, "the socket is bound: it is a server socket".into())),
            Endpoint::Broken => Err(closed()),
        }
    }

    /// SocketBind.
    pub(super) fn bind(&mut self, handle: Option<u32>, at: SocketAddrV4) -> Result<(), Fault> {
        let net = &self.net;
        let entry = entry_of(&mut self.entries, handle)?;
        match entry {
            Endpoint::TcpNew => {
                let listener = net.tcp_bind(at).map_err(|e| io_fault(&e))?;
                *entry = Endpoint::TcpBound { listener, listening: false };
                Ok(())
            }
            Endpoint::UdpNew => {
                let socket = net.udp_bind(at).map_err(|e| io_fault(&e))?;
                *entry = Endpoint::Udp { socket, bound: true, connected: false };
                Ok(())
            }
            Endpoint::TcpBound { .. } | Endpoint::Udp { bound: true, .. } => {
                Err((Err::SockIsBound, "the socket is already bound".into()))
            }
            Endpoint::TcpConnected(_) | Endpoint::Udp { connected: true, .. } => Err(is_connected()),
            // A UDP socket that SocketSendTo bound to a free port.
            Endpoint::Udp { .. } => Err((Err::SockIsBound, "SocketSendTo already bound the socket to a port".into())),
            Endpoint::Broken => Err(closed()),
        }
    }

    /// SocketListen.
    pub(super) fn listen(&mut self, handle: Option<u32>) -> Result<(), Fault> {
        match self.entry(handle)? {
            // uncertain: listening twice is accepted (BSD listen allows it).
            Endpoint::TcpBound { listening, .. } => {
                *listening = true;
                Ok(())
            }
            Endpoint::TcpNew => Err(not_bound()),
            Endpoint::TcpConnected(_) => Err(is_connected()),
            // uncertain: no error is documented for a UDP socket (ERR_SOCK_UNSPEC).
            _ => Err((Err::SockUnspec, "a UDP socket cannot listen".into())),
        }
    }

    /// SocketAccept: waits for a connection on a listening socket; the new socket's
    /// handle and the client's address.
    pub(super) fn accept(&mut self, handle: Option<u32>, deadline: Deadline) -> Result<(u32, Ipv4Addr), Fault> {
        if self.entries.len() >= MAX_SOCKETS {
            return Err((Err::SockUnspec, format!("a task can hold at most {MAX_SOCKETS} sockets")));
        }
        let clock = self.clock.clone();
        let listener = match entry_of(&mut self.entries, handle)? {
            Endpoint::TcpBound { listener, listening: true } => listener,
            Endpoint::TcpNew => return Err(not_bound()),
            Endpoint::TcpConnected(_) => return Err(is_connected()),
            // uncertain: accept on a bound socket that does not listen, or on a UDP
            // socket, has no documented error (ERR_SOCK_UNSPEC; BSD gives EINVAL).
            Endpoint::TcpBound { listening: false, .. } => {
                return Err((Err::SockUnspec, "the socket does not listen (SocketListen first)".into()))
            }
            _ => return Err((Err::SockUnspec, "a UDP socket cannot accept connections".into())),
        };
        let (mut tcp, peer) = loop {
            match poll_accept(&mut **listener)? {
                Some(accepted) => break accepted,
                None => sleep_step(&*clock, deadline, "no connection was accepted")?,
            }
        };
        tcp.set_nonblocking(false).map_err(|e| io_fault(&e))?;
        let ip = match peer {
            SocketAddr::V4(v4) => *v4.ip(),
            SocketAddr::V6(v6) => v6.ip().to_ipv4_mapped().unwrap_or(Ipv4Addr::UNSPECIFIED),
        };
        let new = self.create(false)?;
        self.entries.insert(new, Endpoint::TcpConnected(Stream { tcp, pending: Vec::new(), eof: false }));
        Ok((new, ip))
    }

    /// SocketSend on a connected socket.
    pub(super) fn send(&mut self, handle: Option<u32>, bytes: &[u8], deadline: Deadline) -> Result<(), Fault> {
        let clock = &self.clock;
        let entry = entry_of(&mut self.entries, handle)?;
        let res = match entry {
            Endpoint::TcpConnected(stream) => {
                let timeout = remaining(&**clock, deadline).max(Duration::from_millis(1));
                stream.tcp.set_write_timeout(Some(timeout)).map_err(|e| io_fault(&e))?;
                stream.tcp.write_all(bytes).and_then(|()| stream.tcp.flush())
            }
            Endpoint::Udp { socket, connected: true, .. } => socket.send(bytes).map(|_| ()),
            _ => return Err(not_connected()),
        };
        res.map_err(|e| break_on_close(entry, io_fault(&e)))
    }

    /// SocketSendTo on a UDP socket.
    pub(super) fn send_to(&mut self, handle: Option<u32>, bytes: &[u8], to: SocketAddrV4) -> Result<(), Fault> {
        let net = &self.net;
        let entry = entry_of(&mut self.entries, handle)?;
        if let Endpoint::UdpNew = entry {
            let socket = net.udp_bind(any_port()).map_err(|e| io_fault(&e))?;
            *entry = Endpoint::Udp { socket, bound: false, connected: false };
        }
        match entry {
            Endpoint::Udp { connected: true, .. } => Err(is_connected()),
            Endpoint::Udp { socket, .. } => socket.send_to(bytes, to).map(|_| ()).map_err(|e| io_fault(&e)),
            // uncertain: SocketSendTo is for UDP; on a TCP socket no error is documented.
            _ => Err((Err::SockUnspec, "SocketSendTo needs a UDP socket (SocketCreate \\UDP)".into())),
        }
    }

    /// SocketReceive: waits until `want.min` bytes are there, returns up to `want.max`.
    pub(super) fn receive(&mut self, handle: Option<u32>, want: Want, deadline: Deadline) -> Result<Vec<u8>, Fault> {
        let clock = &self.clock;
        let entry = entry_of(&mut self.entries, handle)?;
        let res = match entry {
            Endpoint::TcpConnected(stream) => receive_stream(&**clock, stream, want, deadline),
            Endpoint::Udp { socket, connected: true, .. } => {
                receive_datagram(&**clock, &mut **socket, want.max, deadline).map(|(bytes, _)| bytes)
            }
            _ => return Err(not_connected()),
        };
        res.map_err(|fault| break_on_close(entry, fault))
    }

    /// SocketReceiveFrom: the next datagram (up to `max` bytes) and its sender.
    pub(super) fn receive_from(
        &mut self,
        handle: Option<u32>,
        max: usize,
        deadline: Deadline,
    ) -> Result<(Vec<u8>, SocketAddr), Fault> {
        let clock = &self.clock;
        match entry_of(&mut self.entries, handle)? {
            Endpoint::Udp { socket, .. } => receive_datagram(&**clock, &mut **socket, max, deadline),
            Endpoint::UdpNew => Err(not_bound()),
            // uncertain: SocketReceiveFrom is for UDP; on a TCP socket no error is documented.
            _ => Err((Err::SockUnspec, "SocketReceiveFrom needs a UDP socket (SocketCreate \\UDP)".into())),
        }
    }

    /// SocketPeek: how many bytes a SocketReceive could take now, without waiting.
    pub(super) fn peek(&mut self, handle: Option<u32>) -> Result<usize, Fault> {
        match self.entry(handle)? {
            Endpoint::TcpConnected(stream) => {
                fill_available(stream)?;
                Ok(stream.pending.len())
            }
            Endpoint::Udp { socket, bound, connected } if *bound || *connected => {
                let mut buf = vec![0u8; 65_536];
                socket.set_nonblocking(true).map_err(|e| io_fault(&e))?;
                let res = socket.peek_from(&mut buf);
                socket.set_nonblocking(false).map_err(|e| io_fault(&e))?;
                match res {
                    Ok((n, _)) => Ok(n),
                    Err(e) if e.kind() == io::ErrorKind::WouldBlock => Ok(0),
                    Err(e) => Err(io_fault(&e)),
                }
            }
            Endpoint::UdpNew | Endpoint::Udp { .. } => Err(not_bound()),
            _ => Err(not_connected()),
        }
    }
}

/// The entry of a socket in use in `entries`; ERR_SOCK_CLOSED otherwise.
fn entry_of(entries: &mut FxHashMap<u32, Endpoint>, handle: Option<u32>) -> Result<&mut Endpoint, Fault> {
    match handle.and_then(|h| entries.get_mut(&h)) {
        None => Err((Err::SockClosed, "the socket is not created or was closed".into())),
        Some(Endpoint::Broken) => Err((Err::SockClosed, "the connection was closed or broken".into())),
        Some(entry) => Ok(entry),
    }
}

// ---- waiting --------------------------------------------------------------------------

/// Time left until `deadline` (zero when past).
fn remaining(clock: &dyn Clock, deadline: Deadline) -> Duration {
    deadline.saturating_sub(clock.elapsed())
}

/// Sleeps one poll step (never past the deadline); ERR_SOCK_TIMEOUT once it is reached.
fn sleep_step(clock: &dyn Clock, deadline: Deadline, what: &str) -> Result<(), Fault> {
    let left = remaining(clock, deadline);
    if left.is_zero() {
        return Err((Err::SockTimeout, format!("{what} within the time allowed")));
    }
    clock.sleep(left.min(POLL_STEP));
    Ok(())
}

/// One non-blocking accept: the connection if one is queued.
type Accepted = (Box<dyn TcpConn>, SocketAddr);

fn poll_accept(listener: &mut dyn TcpListen) -> Result<Option<Accepted>, Fault> {
    listener.set_nonblocking(true).map_err(|e| io_fault(&e))?;
    let res = listener.accept();
    listener.set_nonblocking(false).map_err(|e| io_fault(&e))?;
    match res {
        Ok(accepted) => Ok(Some(accepted)),
        Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::Interrupted) => Ok(None),
        Err(e) => Err(io_fault(&e)),
    }
}

/// Reads, without waiting, what the peer has sent, up to the read-ahead cap.
fn fill_available(stream: &mut Stream) -> Result<(), Fault> {
    stream.tcp.set_nonblocking(true).map_err(|e| io_fault(&e))?;
    let res = read_into(stream);
    stream.tcp.set_nonblocking(false).map_err(|e| io_fault(&e))?;
    res
}

/// Reads until the socket has nothing more (WouldBlock, or a timeout in blocking
/// mode), the peer closed, or the read-ahead is full.
fn read_into(stream: &mut Stream) -> Result<(), Fault> {
    let mut buf = [0u8; 4096];
    while !stream.eof && stream.pending.len() < PENDING_CAP {
        match stream.tcp.read(&mut buf) {
            Ok(0) => stream.eof = true,
            Ok(n) => stream.pending.extend_from_slice(&buf[..n]),
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut) => return Ok(()),
            Err(e) => return Err(io_fault(&e)),
        }
    }
    Ok(())
}

/// One step of a stream receive without waiting: the bytes when `want` is met,
/// ERR_SOCK_CLOSED when it never can be, `None` while more must arrive.
fn poll_stream(stream: &mut Stream, want: Want) -> Result<Option<Vec<u8>>, Fault> {
    fill_available(stream)?;
    if stream.pending.len() >= want.min.max(1) {
        let n = stream.pending.len().min(want.max);
        return Ok(Some(stream.pending.drain(..n).collect()));
    }
    if stream.eof {
        return Err(closed_by_peer());
    }
    Ok(None)
}

fn receive_stream(clock: &dyn Clock, stream: &mut Stream, want: Want, deadline: Deadline) -> Result<Vec<u8>, Fault> {
    loop {
        if let Some(bytes) = poll_stream(stream, want)? {
            return Ok(bytes);
        }
        let left = remaining(clock, deadline);
        if left.is_zero() {
            return Err((Err::SockTimeout, "no data arrived within the time allowed".into()));
        }
        // Block until something arrives (or the time is up); the next poll takes it.
        stream.tcp.set_read_timeout(Some(left)).map_err(|e| io_fault(&e))?;
        let mut buf = [0u8; 4096];
        match stream.tcp.read(&mut buf) {
            Ok(0) => stream.eof = true,
            Ok(n) => stream.pending.extend_from_slice(&buf[..n]),
            Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut) => {}
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(io_fault(&e)),
        }
    }
}

/// The next datagram, cut to `max` bytes (the rest of it is lost, as with recvfrom).
fn receive_datagram(
    clock: &dyn Clock,
    socket: &mut dyn UdpConn,
    max: usize,
    deadline: Deadline,
) -> Result<(Vec<u8>, SocketAddr), Fault> {
    let mut buf = vec![0u8; 65_536];
    loop {
        let left = remaining(clock, deadline);
        let res = if left.is_zero() {
            socket.set_nonblocking(true).map_err(|e| io_fault(&e))?;
            let res = socket.recv_from(&mut buf);
            socket.set_nonblocking(false).map_err(|e| io_fault(&e))?;
            res
        } else {
            socket.set_read_timeout(Some(left)).map_err(|e| io_fault(&e))?;
            socket.recv_from(&mut buf)
        };
        match res {
            Ok((n, from)) => {
                buf.truncate(n.min(max));
                return Ok((buf, from));
            }
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut) => {
                if remaining(clock, deadline).is_zero() {
                    return Err((Err::SockTimeout, "no datagram arrived within the time allowed".into()));
                }
            }
            Err(e) => return Err(io_fault(&e)),
        }
    }
}

// ---- errors ---------------------------------------------------------------------------

/// A socket whose connection broke becomes closed (SOCKET_CLOSED) for good.
fn break_on_close(entry: &mut Endpoint, fault: Fault) -> Fault {
    if fault.0 == Err::SockClosed {
        *entry = Endpoint::Broken;
    }
    fault
}

fn closed() -> Fault {
    (Err::SockClosed, "the connection was closed or broken".into())
}

fn closed_by_peer() -> Fault {
    (Err::SockClosed, "the remote computer closed the connection".into())
}

fn is_connected() -> Fault {
    (Err::SockIsConn, "the socket is already connected".into())
}

fn not_connected() -> Fault {
    (Err::SockNotConn, "the socket is not connected".into())
}

fn not_bound() -> Fault {
    (Err::SockNotBound, "the socket is not bound (SocketBind first)".into())
}

/// Any local address, a port of the OS's choosing.
fn any_port() -> SocketAddrV4 {
    SocketAddrV4::new(Ipv4Addr::UNSPECIFIED, 0)
}

/// The RAPID error for an OS socket error.
// uncertain: the manual names the errors but not the OS conditions behind them; a
// refused connection is read as a closed one (the peer answered with a reset).
fn io_fault(e: &io::Error) -> Fault {
    use io::ErrorKind as K;
    let err = match e.kind() {
        K::AddrInUse => Err::SockAddrInUse,
        K::AddrNotAvailable | K::InvalidInput => Err::SockAddrInvalid,
        K::ConnectionRefused | K::ConnectionReset | K::ConnectionAborted | K::BrokenPipe | K::UnexpectedEof => {
            Err::SockClosed
        }
        K::NotConnected => Err::SockNotConn,
        K::TimedOut | K::WouldBlock => Err::SockTimeout,
        K::NetworkUnreachable | K::HostUnreachable | K::NetworkDown => Err::SockNetUnreach,
        _ => Err::SockUnspec,
    };
    (err, format!("socket error: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn loopback_any_port() -> SocketAddrV4 {
        SocketAddrV4::new(Ipv4Addr::LOCALHOST, 0)
    }

    /// A table on a network where no peer ever sends, on a clock that moves only when
    /// the table waits (the std network is tested in `rapid_controller::host_std`).
    fn silent_table() -> SocketState {
        let clock = Rc::new(StoppedClock::default());
        let mut table = SocketState::default();
        table.set_network(Box::new(rapid_vm::ext::SilentNetwork::new(clock.clone())), clock);
        table
    }

    #[test]
    fn states_follow_the_instructions() {
        let mut table = silent_table();
        assert_eq!(table.status(None), Status::Closed);
        let tcp = Some(table.create(false).unwrap());
        assert_eq!(table.status(tcp), Status::Created);
        assert_eq!(table.listen(tcp).unwrap_err().0, Err::SockNotBound);
        table.bind(tcp, loopback_any_port()).unwrap();
        assert_eq!(table.status(tcp), Status::Bound);
        assert_eq!(table.bind(tcp, loopback_any_port()).unwrap_err().0, Err::SockIsBound);
        table.listen(tcp).unwrap();
        assert_eq!(table.status(tcp), Status::Listening);
        assert_eq!(table.bound_addrs().len(), 1);
        table.close(tcp);
        assert_eq!(table.status(tcp), Status::Closed);
        assert_eq!(table.listen(tcp).unwrap_err().0, Err::SockClosed);
    }

    #[test]
    fn handles_are_not_reused_and_the_table_is_bounded() {
        let mut table = SocketState::default();
        let first = table.create(true).unwrap();
        table.close(Some(first));
        let second = table.create(true).unwrap();
        assert_ne!(first, second, "a stale socketdev must not reach a new socket");
        for _ in 1..MAX_SOCKETS {
            table.create(false).unwrap();
        }
        assert_eq!(table.create(false).unwrap_err().0, Err::SockUnspec);
        table.close_all();
        assert_eq!(table.status(Some(second)), Status::Closed);
    }

    #[test]
    fn os_errors_map_to_socket_errors() {
        use io::ErrorKind as K;
        let cases = [
            (K::AddrInUse, Err::SockAddrInUse),
            (K::AddrNotAvailable, Err::SockAddrInvalid),
            (K::ConnectionReset, Err::SockClosed),
            (K::BrokenPipe, Err::SockClosed),
            (K::TimedOut, Err::SockTimeout),
            (K::HostUnreachable, Err::SockNetUnreach),
            (K::PermissionDenied, Err::SockUnspec),
        ];
        for (kind, err) in cases {
            assert_eq!(io_fault(&io::Error::from(kind)).0, err, "{kind:?}");
        }
    }

    #[test]
    fn a_receive_waits_no_longer_than_its_deadline() {
        let mut table = silent_table();
        let udp = Some(table.create(true).unwrap());
        table.bind(udp, loopback_any_port()).unwrap();
        let started = table.now();
        let fault = table.receive_from(udp, 80, started + Duration::from_millis(50)).unwrap_err();
        assert_eq!(fault.0, Err::SockTimeout);
        let waited = table.now() - started;
        assert!(waited >= Duration::from_millis(50) && waited < Duration::from_secs(5), "{waited:?}");
    }
}
