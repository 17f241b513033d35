//! The network a task's sockets reach (SocketCreate ... SocketClose): TCP and UDP over
//! IPv4, as `std::net` offers them. The socket table (`rapid_controller::bindings::sockets`)
//! keeps the RAPID states, the read-ahead and the deadlines; a [`Network`] makes the
//! endpoints, which block no longer than the timeouts the table sets.

use std::io;
use std::net::{SocketAddr, SocketAddrV4};
use std::time::Duration;

/// A connected TCP stream. Reads and writes block (within the timeouts set) unless
/// non-blocking mode is on, when they fail with [`io::ErrorKind::WouldBlock`].
pub trait TcpConn: io::Read + io::Write {
    fn set_read_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()>;
    fn set_write_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()>;
    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()>;
}

/// A bound TCP socket that takes connections (it listens from the bind on).
pub trait TcpListen {
    /// The next queued connection and its peer; with non-blocking mode on,
    /// [`io::ErrorKind::WouldBlock`] when none is queued.
    fn accept(&mut self) -> io::Result<(Box<dyn TcpConn>, SocketAddr)>;
    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()>;
    fn local_addr(&self) -> io::Result<SocketAddr>;
}

/// A UDP socket.
pub trait UdpConn {
    /// Fixes the peer of [`UdpConn::send`] and of the datagrams received.
    fn connect(&mut self, to: SocketAddrV4) -> io::Result<()>;
    fn send(&mut self, bytes: &[u8]) -> io::Result<usize>;
    fn send_to(&mut self, bytes: &[u8], to: SocketAddrV4) -> io::Result<usize>;
    /// The next datagram into `buf` (cut to its size) and its sender.
    fn recv_from(&mut self, buf: &mut [u8]) -> io::Result<(usize, SocketAddr)>;
    /// [`UdpConn::recv_from`] that leaves the datagram queued.
    fn peek_from(&mut self, buf: &mut [u8]) -> io::Result<(usize, SocketAddr)>;
    fn set_read_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()>;
    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()>;
    fn local_addr(&self) -> io::Result<SocketAddr>;
}

/// Makes the endpoints of a task's sockets.
pub trait Network {
    /// A TCP connection to `to`, waiting at most `timeout` for it.
    fn tcp_connect(&self, to: SocketAddrV4, timeout: Duration) -> io::Result<Box<dyn TcpConn>>;
    /// A TCP socket bound to `at` and listening (port 0: one the network chooses).
    fn tcp_bind(&self, at: SocketAddrV4) -> io::Result<Box<dyn TcpListen>>;
    /// A UDP socket bound to `at` (port 0: one the network chooses).
    fn udp_bind(&self, at: SocketAddrV4) -> io::Result<Box<dyn UdpConn>>;
    /// Whether this world has no network at all (SocketCreate then fails at once).
    fn is_closed(&self) -> bool {
        false
    }
}

/// The network of a closed world: there is none.
#[derive(Debug, Default)]
pub struct NoNetwork;

fn none() -> io::Error {
    io::Error::new(io::ErrorKind::Unsupported, "this controller was given no network")
}

impl Network for NoNetwork {
    fn tcp_connect(&self, _: SocketAddrV4, _: Duration) -> io::Result<Box<dyn TcpConn>> {
        Err(none())
    }
    fn tcp_bind(&self, _: SocketAddrV4) -> io::Result<Box<dyn TcpListen>> {
        Err(none())
    }
    fn udp_bind(&self, _: SocketAddrV4) -> io::Result<Box<dyn UdpConn>> {
        Err(none())
    }
    fn is_closed(&self) -> bool {
        true
    }
}
