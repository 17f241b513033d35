//! Worlds held in memory, for tests and for embedders that give a program a scripted
//! outside world: a file system of maps ([`MemoryFs`]) that records what was asked of
//! it, and a network whose peers never answer ([`SilentNetwork`]): every wait on it
//! runs to its timeout on the clock it was given, at once.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::io::{self, Read, Seek, SeekFrom, Write};
use std::net::{SocketAddr, SocketAddrV4};
use std::path::{Component, Path, PathBuf};
use std::rc::Rc;
use std::time::{Duration, SystemTime};

use super::clock::{Clock, StoppedClock};
use super::files::{FileKind, FileMeta, FileSystem, HostFile, OpenMode};
use super::net::{Network, TcpConn, TcpListen, UdpConn};

type Bytes = Rc<RefCell<Vec<u8>>>;

enum Node {
    File(Bytes),
    Dir,
}

/// A file system in memory. `/` exists; everything else is made by the program (or by
/// [`MemoryFs::put`]). It has no links, so every path is its own canonical form.
#[derive(Default)]
pub struct MemoryFs {
    nodes: RefCell<BTreeMap<PathBuf, Node>>,
    calls: RefCell<Vec<String>>,
}

impl MemoryFs {
    pub fn new() -> MemoryFs {
        MemoryFs::default()
    }

    /// A file with `bytes` at `path`, its folders made as needed.
    pub fn put(&self, path: impl AsRef<Path>, bytes: &[u8]) {
        let path = clean(path.as_ref());
        if let Some(parent) = path.parent() {
            let _ = self.create_dir_all(parent);
        }
        self.nodes.borrow_mut().insert(path, Node::File(Rc::new(RefCell::new(bytes.to_vec()))));
    }

    /// The content of the file at `path`.
    pub fn get(&self, path: impl AsRef<Path>) -> Option<Vec<u8>> {
        match self.nodes.borrow().get(&clean(path.as_ref())) {
            Some(Node::File(bytes)) => Some(bytes.borrow().clone()),
            _ => None,
        }
    }

    /// Every path that exists, in order.
    pub fn paths(&self) -> Vec<PathBuf> {
        self.nodes.borrow().keys().cloned().collect()
    }

    /// What was asked, oldest first: `"open /x/HOME/a.txt"`, `"read_dir /x/HOME"`...
    pub fn calls(&self) -> Vec<String> {
        self.calls.borrow().clone()
    }

    fn note(&self, what: &str, path: &Path) {
        self.calls.borrow_mut().push(format!("{what} {}", path.display()));
    }

    fn kind(&self, path: &Path) -> Option<FileKind> {
        if path.parent().is_none() {
            return Some(FileKind::Dir);
        }
        self.nodes.borrow().get(path).map(|node| match node {
            Node::File(_) => FileKind::File,
            Node::Dir => FileKind::Dir,
        })
    }

    fn need_parent(&self, path: &Path) -> io::Result<()> {
        match path.parent().map(|p| self.kind(p)) {
            Some(Some(FileKind::Dir)) | None => Ok(()),
            _ => Err(not_found(path)),
        }
    }
}

/// `path` with `.` and `..` applied (the root stays the root).
fn clean(path: &Path) -> PathBuf {
    let mut out = PathBuf::from("/");
    for part in path.components() {
        match part {
            Component::Normal(name) => out.push(name),
            Component::ParentDir => {
                out.pop();
            }
            _ => {}
        }
    }
    out
}

fn not_found(path: &Path) -> io::Error {
    io::Error::new(io::ErrorKind::NotFound, format!("`{}` does not exist", path.display()))
}

fn exists(path: &Path) -> io::Error {
    io::Error::new(io::ErrorKind::AlreadyExists, format!("`{}` exists", path.display()))
}

impl FileSystem for MemoryFs {
    fn open(&self, path: &Path, mode: OpenMode) -> io::Result<Box<dyn HostFile>> {
        self.note("open", path);
        let path = clean(path);
        let bytes = match self.nodes.borrow().get(&path) {
            Some(Node::File(bytes)) => Some(bytes.clone()),
            Some(Node::Dir) => return Err(io::Error::other(format!("`{}` is a directory", path.display()))),
            None => None,
        };
        let bytes = match bytes {
            Some(bytes) => bytes,
            None if mode.create => {
                self.need_parent(&path)?;
                let bytes: Bytes = Rc::default();
                self.nodes.borrow_mut().insert(path, Node::File(bytes.clone()));
                bytes
            }
            None => return Err(not_found(&path)),
        };
        if mode.truncate {
            bytes.borrow_mut().clear();
        }
        Ok(Box::new(MemoryFile { bytes, pos: 0, append: mode.append }))
    }

    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        self.note("read", path);
        self.get(path).ok_or_else(|| not_found(path))
    }

    fn write_atomic(&self, path: &Path, bytes: &[u8]) -> io::Result<()> {
        self.note("write_atomic", path);
        let path = clean(path);
        self.need_parent(&path)?;
        self.nodes.borrow_mut().insert(path, Node::File(Rc::new(RefCell::new(bytes.to_vec()))));
        Ok(())
    }

    fn metadata(&self, path: &Path) -> io::Result<FileMeta> {
        let path = clean(path);
        let kind = self.kind(&path).ok_or_else(|| not_found(&path))?;
        let len = match self.nodes.borrow().get(&path) {
            Some(Node::File(bytes)) => bytes.borrow().len() as u64,
            _ => 0,
        };
        let time = Some(SystemTime::UNIX_EPOCH);
        Ok(FileMeta { kind, len, modified: time, accessed: time, changed: time })
    }

    fn symlink_metadata(&self, path: &Path) -> io::Result<FileMeta> {
        self.metadata(path)
    }

    fn canonicalize(&self, path: &Path) -> io::Result<PathBuf> {
        let path = clean(path);
        self.kind(&path).map(|_| path.clone()).ok_or_else(|| not_found(&path))
    }

    fn read_dir(&self, path: &Path) -> io::Result<Vec<String>> {
        self.note("read_dir", path);
        let path = clean(path);
        if self.kind(&path) != Some(FileKind::Dir) {
            return Err(not_found(&path));
        }
        let nodes = self.nodes.borrow();
        let names = nodes
            .keys()
            .filter(|p| p.parent() == Some(path.as_path()))
            .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
            .collect();
        Ok(names)
    }

    fn create_dir(&self, path: &Path) -> io::Result<()> {
        self.note("create_dir", path);
        let path = clean(path);
        if self.kind(&path).is_some() {
            return Err(exists(&path));
        }
        self.need_parent(&path)?;
        self.nodes.borrow_mut().insert(path, Node::Dir);
        Ok(())
    }

    fn create_dir_all(&self, path: &Path) -> io::Result<()> {
        let path = clean(path);
        for dir in path.ancestors().collect::<Vec<_>>().into_iter().rev() {
            match self.kind(dir) {
                Some(FileKind::Dir) => {}
                Some(_) => return Err(exists(dir)),
                None => {
                    self.nodes.borrow_mut().insert(dir.to_path_buf(), Node::Dir);
                }
            }
        }
        Ok(())
    }

    fn remove_dir(&self, path: &Path) -> io::Result<()> {
        self.note("remove_dir", path);
        let path = clean(path);
        if self.kind(&path) != Some(FileKind::Dir) {
            return Err(not_found(&path));
        }
        if !self.read_dir(&path)?.is_empty() {
            return Err(io::Error::other(format!("`{}` is not empty", path.display())));
        }
        self.nodes.borrow_mut().remove(&path);
        Ok(())
    }

    fn remove_file(&self, path: &Path) -> io::Result<()> {
        self.note("remove_file", path);
        let path = clean(path);
        match self.kind(&path) {
            Some(FileKind::File) => {
                self.nodes.borrow_mut().remove(&path);
                Ok(())
            }
            _ => Err(not_found(&path)),
        }
    }

    fn rename(&self, from: &Path, to: &Path) -> io::Result<()> {
        self.note("rename", from);
        let (from, to) = (clean(from), clean(to));
        self.need_parent(&to)?;
        let node = self.nodes.borrow_mut().remove(&from).ok_or_else(|| not_found(&from))?;
        self.nodes.borrow_mut().insert(to, node);
        Ok(())
    }

    fn copy(&self, from: &Path, to: &Path) -> io::Result<()> {
        self.note("copy", from);
        let bytes = self.get(from).ok_or_else(|| not_found(from))?;
        self.need_parent(&clean(to))?;
        self.put(to, &bytes);
        Ok(())
    }

    fn space(&self, _: &Path) -> io::Result<(u64, u64)> {
        let used: u64 = self.paths().iter().filter_map(|p| self.get(p)).map(|b| b.len() as u64).sum();
        Ok((1 << 30, (1u64 << 30).saturating_sub(used)))
    }
}

/// An open file of a [`MemoryFs`].
struct MemoryFile {
    bytes: Bytes,
    pos: u64,
    append: bool,
}

impl Read for MemoryFile {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let bytes = self.bytes.borrow();
        let start = (self.pos as usize).min(bytes.len());
        let n = buf.len().min(bytes.len() - start);
        buf[..n].copy_from_slice(&bytes[start..start + n]);
        self.pos += n as u64;
        Ok(n)
    }
}

impl Write for MemoryFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let mut bytes = self.bytes.borrow_mut();
        if self.append {
            self.pos = bytes.len() as u64;
        }
        let start = self.pos as usize;
        if bytes.len() < start {
            bytes.resize(start, 0);
        }
        let overlap = buf.len().min(bytes.len() - start);
        bytes[start..start + overlap].copy_from_slice(&buf[..overlap]);
        bytes.extend_from_slice(&buf[overlap..]);
        self.pos += buf.len() as u64;
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

impl Seek for MemoryFile {
    fn seek(&mut self, to: SeekFrom) -> io::Result<u64> {
        let len = self.bytes.borrow().len() as i64;
        let pos = match to {
            SeekFrom::Start(n) => n as i64,
            SeekFrom::End(d) => len + d,
            SeekFrom::Current(d) => self.pos as i64 + d,
        };
        if pos < 0 {
            return Err(io::Error::new(io::ErrorKind::InvalidInput, "a seek before the start of the file"));
        }
        self.pos = pos as u64;
        Ok(self.pos)
    }
}

/// A network where connections and binds succeed and no peer ever sends: sends are
/// kept ([`SilentNetwork::sent`]), and a receive that would wait lets its timeout pass
/// on `clock` and finds nothing.
pub struct SilentNetwork {
    clock: Rc<StoppedClock>,
    sent: Rc<RefCell<Vec<Vec<u8>>>>,
}

impl SilentNetwork {
    pub fn new(clock: Rc<StoppedClock>) -> SilentNetwork {
        SilentNetwork { clock, sent: Rc::default() }
    }

    /// What the program sent, one entry per send.
    pub fn sent(&self) -> Rc<RefCell<Vec<Vec<u8>>>> {
        self.sent.clone()
    }
}

struct SilentConn {
    clock: Rc<StoppedClock>,
    sent: Rc<RefCell<Vec<Vec<u8>>>>,
    read_timeout: Option<Duration>,
    nonblocking: bool,
    local: SocketAddr,
}

impl SilentConn {
    /// A receive: nothing ever comes; a blocking one waits out its timeout first.
    fn nothing(&self) -> io::Error {
        if !self.nonblocking {
            // A blocking read without a timeout would wait for ever: a day stands in.
            self.clock.sleep(self.read_timeout.unwrap_or(Duration::from_secs(86_400)));
        }
        io::Error::new(io::ErrorKind::WouldBlock, "nothing arrived")
    }
}

impl Read for SilentConn {
    fn read(&mut self, _: &mut [u8]) -> io::Result<usize> {
        Err(self.nothing())
    }
}

impl Write for SilentConn {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.sent.borrow_mut().push(buf.to_vec());
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

impl TcpConn for SilentConn {
    fn set_read_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()> {
        self.read_timeout = timeout;
        Ok(())
    }
    fn set_write_timeout(&mut self, _: Option<Duration>) -> io::Result<()> {
        Ok(())
    }
    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()> {
        self.nonblocking = nonblocking;
        Ok(())
    }
}

impl TcpListen for SilentConn {
    fn accept(&mut self) -> io::Result<(Box<dyn TcpConn>, SocketAddr)> {
        Err(self.nothing())
    }
    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()> {
        self.nonblocking = nonblocking;
        Ok(())
    }
    fn local_addr(&self) -> io::Result<SocketAddr> {
        Ok(self.local)
    }
}

impl UdpConn for SilentConn {
    fn connect(&mut self, _: SocketAddrV4) -> io::Result<()> {
        Ok(())
    }
    fn send(&mut self, bytes: &[u8]) -> io::Result<usize> {
        self.write(bytes)
    }
    fn send_to(&mut self, bytes: &[u8], _: SocketAddrV4) -> io::Result<usize> {
        self.write(bytes)
    }
    fn recv_from(&mut self, _: &mut [u8]) -> io::Result<(usize, SocketAddr)> {
        Err(self.nothing())
    }
    fn peek_from(&mut self, _: &mut [u8]) -> io::Result<(usize, SocketAddr)> {
        Err(self.nothing())
    }
    fn set_read_timeout(&mut self, timeout: Option<Duration>) -> io::Result<()> {
        self.read_timeout = timeout;
        Ok(())
    }
    fn set_nonblocking(&mut self, nonblocking: bool) -> io::Result<()> {
        self.nonblocking = nonblocking;
        Ok(())
    }
    fn local_addr(&self) -> io::Result<SocketAddr> {
        Ok(self.local)
    }
}

impl SilentNetwork {
    fn conn(&self, local: SocketAddrV4) -> SilentConn {
        let local = SocketAddr::V4(local);
        SilentConn { clock: self.clock.clone(), sent: self.sent.clone(), read_timeout: None, nonblocking: false, local }
    }
}

impl Network for SilentNetwork {
    fn tcp_connect(&self, _: SocketAddrV4, _: Duration) -> io::Result<Box<dyn TcpConn>> {
        Ok(Box::new(self.conn(SocketAddrV4::new(std::net::Ipv4Addr::LOCALHOST, 40_000))))
    }
    fn tcp_bind(&self, at: SocketAddrV4) -> io::Result<Box<dyn TcpListen>> {
        Ok(Box::new(self.conn(at)))
    }
    fn udp_bind(&self, at: SocketAddrV4) -> io::Result<Box<dyn UdpConn>> {
        Ok(Box::new(self.conn(at)))
    }
}
