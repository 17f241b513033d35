//! The outside world of a task: its file system, its network and its clocks, behind
//! traits an embedder implements. The VM never reaches the host itself; whoever builds
//! a VM hands it a [`World`] ([`crate::Vm::set_world`]), as a wasmtime embedder hands
//! its store the `WasiView` it owns. The pendant is the other half of the outside world
//! ([`crate::host::Host`], passed to each run).
//!
//! What a VM knows without a world is nothing: the default [`World::closed`] has no
//! file system, no network, and a clock stopped at 1970-01-01 00:00 UTC. The std
//! implementations (the host's disk, sockets and clocks) live with the front ends
//! (`rapid_controller::host_std`), which give every task they boot a world of its own.
//!
//! Errors cross the traits as [`std::io::Error`]: the file and socket built-ins map
//! them to RAPID errors by their kind (ERR_FILEOPEN, ERR_SOCK_TIMEOUT, ...), whatever
//! world produced them.

pub mod clock;
pub mod devices;
pub mod files;
pub mod memory;
pub mod net;

use std::rc::Rc;

pub use clock::{Clock, StoppedClock};
pub use files::{FileKind, FileMeta, FileSystem, HostFile, NoFileSystem, OpenMode};
pub use net::{Network, NoNetwork, TcpConn, TcpListen, UdpConn};

/// What a task reaches outside the interpreter (the pendant aside).
pub struct World {
    /// The disk the file devices (`HOME:`, `TEMP:`, ...) live on, and the module files.
    pub files: Box<dyn FileSystem>,
    /// The sockets (SocketCreate ...).
    pub net: Box<dyn Network>,
    /// The calendar (CDate, CTime, GetTime) and the monotonic clock socket waits use.
    pub clock: Rc<dyn Clock>,
}

impl World {
    /// No file system, no network, a stopped clock.
    pub fn closed() -> World {
        World { files: Box::new(NoFileSystem), net: Box::new(NoNetwork), clock: Rc::new(StoppedClock::default()) }
    }
}

impl Default for World {
    fn default() -> World {
        World::closed()
    }
}
