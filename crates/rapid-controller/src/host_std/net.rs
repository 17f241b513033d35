//! The host's network (`std::net`) as the VM's [`Network`].

use std::io::{self, Read, Write};
use std::net::{SocketAddr, SocketAddrV4, TcpListener, TcpStream, UdpSocket};
use std::time::Duration;

use rapid_vm::world::{Network, TcpConn, TcpListen, UdpConn};

/// TCP and UDP sockets of the host.
#[derive(Debug, Default, Clone, Copy)]
pub struct StdNetwork;

impl Network for StdNetwork {
    fn tcp_connect(&self, to: SocketAddrV4, timeout: Duration) -> io::Result<Box<dyn TcpConn>> {
        Ok(Box::new(Tcp(TcpStream::connect_timeout(&SocketAddr::V4(to), timeout)?)))
    }

    fn tcp_bind(&self, at: SocketAddrV4) -> io::Result<Box<dyn TcpListen>> {
        Ok(Box::new(Listener(TcpListener::bind(at)?)))
    }

    fn udp_bind(&self, at: SocketAddrV4) -> io::Result<Box<dyn UdpConn>> {
        Ok(Box::new(Udp(UdpSocket::bind(at)?)))
    }
}

/// A connected std TCP stream.
struct Tcp(TcpStream);

impl Read for Tcp {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        self.0.read(buf)
    }
}

impl Write for Tcp {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.0.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.0.flush()
    }
}

impl TcpConn for Tcp {
    fn set_read_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()> {
        self.0.set_read_timeout(timeout)
    }

    fn set_write_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()> {
        self.0.set_write_timeout(timeout)
    }

    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()> {
        self.0.set_nonblocking(nonblocking)
    }
}

/// A std TCP listener (std binds and listens in one call).
struct Listener(TcpListener);

impl TcpListen for Listener {
    fn accept(&mut self) -> io::Result<(Box<dyn TcpConn>, SocketAddr)> {
        let (tcp, peer) = self.0.accept()?;
        Ok((Box::new(Tcp(tcp)), peer))
    }

    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()> {
        self.0.set_nonblocking(nonblocking)
    }

    fn local_addr(&self) -> io::Result<SocketAddr> {
        self.0.local_addr()
    }
}

/// A std UDP socket.
struct Udp(UdpSocket);

impl UdpConn for Udp {
    fn connect(&mut self, to: SocketAddrV4) -> io::Result<()> {
        self.0.connect(to)
    }

    fn send(&mut self, bytes: &[u8]) -> io::Result<usize> {
        self.0.send(bytes)
    }

    fn send_to(&mut self, bytes: &[u8], to: SocketAddrV4) -> io::Result<usize> {
        self.0.send_to(bytes, to)
    }

    fn recv_from(&mut self, buf: &mut [u8]) -> io::Result<(usize, SocketAddr)> {
        self.0.recv_from(buf)
    }

    fn peek_from(&mut self, buf: &mut [u8]) -> io::Result<(usize, SocketAddr)> {
        self.0.peek_from(buf)
    }

    fn set_read_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()> {
        self.0.set_read_timeout(timeout)
    }

    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()> {
        self.0.set_nonblocking(nonblocking)
    }

    fn local_addr(&self) -> io::Result<SocketAddr> {
        self.0.local_addr()
    }
}

#[cfg(test)]
mod tests {
    use std::net::Ipv4Addr;
    use std::time::Instant;

    use super::*;

    fn loopback_any_port() -> SocketAddrV4 {
        SocketAddrV4::new(Ipv4Addr::LOCALHOST, 0)
    }

    #[test]
    fn a_udp_receive_waits_its_timeout_on_the_host() {
        let mut udp = StdNetwork.udp_bind(loopback_any_port()).expect("a loopback socket");
        udp.set_read_timeout(Some(Duration::from_millis(50))).unwrap();
        let started = Instant::now();
        let err = udp.recv_from(&mut [0u8; 16]).unwrap_err();
        assert!(matches!(err.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut), "{err:?}");
        let waited = started.elapsed();
        assert!(waited >= Duration::from_millis(45) && waited < Duration::from_secs(5), "{waited:?}");
    }

    #[test]
    fn a_listener_accepts_a_connection_and_bytes_go_through() {
        let mut listener = StdNetwork.tcp_bind(loopback_any_port()).expect("a loopback listener");
        let SocketAddr::V4(at) = listener.local_addr().unwrap() else { panic!("an IPv4 address") };
        let mut client = StdNetwork.tcp_connect(at, Duration::from_secs(5)).expect("connects");
        let (mut server, peer) = listener.accept().expect("accepts");
        assert!(peer.ip().is_loopback());
        client.write_all(b"ping").unwrap();
        client.flush().unwrap();
        server.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
        let mut buf = [0u8; 4];
        server.read_exact(&mut buf).unwrap();
        assert_eq!(&buf, b"ping");
    }
}
