//! The file system a task's file devices live on, as host paths. The VM keeps the
//! sandbox (which device is which folder under the controller root, and which paths
//! are refused: `world/devices.rs`) so every world gets the same rules; a
//! [`FileSystem`] only does what it is asked on the paths the sandbox let through.

use std::io;
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// An open file: read, written and positioned as the file built-ins need (Open, Write,
/// ReadStr, Rewind, the execution log SpyStart writes).
pub trait HostFile: io::Read + io::Write + io::Seek {}

impl<T: io::Read + io::Write + io::Seek> HostFile for T {}

/// How a file is opened (as `std::fs::OpenOptions` says it).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct OpenMode {
    pub read: bool,
    pub write: bool,
    /// Made when it does not exist (with `write`).
    pub create: bool,
    /// Every write goes to the end.
    pub append: bool,
    /// Emptied when opened.
    pub truncate: bool,
}

/// What a path is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    File,
    Dir,
    Symlink,
    Fifo,
    BlockDevice,
    CharDevice,
    Other,
}

/// What the file functions read of a path (FileSize, FileTimeDnum, IsFile).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileMeta {
    pub kind: FileKind,
    /// Size in bytes.
    pub len: u64,
    /// Last modification, last access and last status change (None where the file
    /// system keeps no such time).
    pub modified: Option<SystemTime>,
    pub accessed: Option<SystemTime>,
    pub changed: Option<SystemTime>,
}

/// A disk. Paths are host paths under the controller root the sandbox resolved; every
/// call may fail with the [`io::Error`] the built-ins report (its kind picks the RAPID
/// error, its text goes into the message).
pub trait FileSystem {
    /// Opens (or makes) the file at `path`.
    fn open(&self, path: &Path, mode: OpenMode) -> io::Result<Box<dyn HostFile>>;
    /// The whole content of a file (Load, TextTabInstall).
    fn read(&self, path: &Path) -> io::Result<Vec<u8>>;
    /// Replaces the file at `path` with `bytes` so a crash leaves the old or the new
    /// content, never a torn file (Save, SaveCfgData).
    fn write_atomic(&self, path: &Path, bytes: &[u8]) -> io::Result<()>;
    /// What `path` is, following symbolic links.
    fn metadata(&self, path: &Path) -> io::Result<FileMeta>;
    /// What `path` is itself (a link is a [`FileKind::Symlink`]).
    fn symlink_metadata(&self, path: &Path) -> io::Result<FileMeta>;
    /// `path` with every link followed and `.`/`..` applied (it must exist).
    fn canonicalize(&self, path: &Path) -> io::Result<PathBuf>;
    /// The names in directory `path`, in any order.
    fn read_dir(&self, path: &Path) -> io::Result<Vec<String>>;
    /// Makes directory `path` (its parent must exist).
    fn create_dir(&self, path: &Path) -> io::Result<()>;
    /// Makes directory `path` and its missing parents.
    fn create_dir_all(&self, path: &Path) -> io::Result<()>;
    /// Removes the empty directory `path`.
    fn remove_dir(&self, path: &Path) -> io::Result<()>;
    fn remove_file(&self, path: &Path) -> io::Result<()>;
    fn rename(&self, from: &Path, to: &Path) -> io::Result<()>;
    fn copy(&self, from: &Path, to: &Path) -> io::Result<()>;
    /// Total and free (available to the program) bytes of the file system holding
    /// `path` (FSSize).
    fn space(&self, path: &Path) -> io::Result<(u64, u64)>;
}

/// The file system of a closed world: every call fails.
#[derive(Debug, Default)]
pub struct NoFileSystem;

fn none() -> io::Error {
    io::Error::new(io::ErrorKind::Unsupported, "this controller was given no file system")
}

impl FileSystem for NoFileSystem {
    fn open(&self, _: &Path, _: OpenMode) -> io::Result<Box<dyn HostFile>> {
        Err(none())
    }
    fn read(&self, _: &Path) -> io::Result<Vec<u8>> {
        Err(none())
    }
    fn write_atomic(&self, _: &Path, _: &[u8]) -> io::Result<()> {
        Err(none())
    }
    fn metadata(&self, _: &Path) -> io::Result<FileMeta> {
        Err(none())
    }
    fn symlink_metadata(&self, _: &Path) -> io::Result<FileMeta> {
        Err(none())
    }
    fn canonicalize(&self, _: &Path) -> io::Result<PathBuf> {
        Err(none())
    }
    fn read_dir(&self, _: &Path) -> io::Result<Vec<String>> {
        Err(none())
    }
    fn create_dir(&self, _: &Path) -> io::Result<()> {
        Err(none())
    }
    fn create_dir_all(&self, _: &Path) -> io::Result<()> {
        Err(none())
    }
    fn remove_dir(&self, _: &Path) -> io::Result<()> {
        Err(none())
    }
    fn remove_file(&self, _: &Path) -> io::Result<()> {
        Err(none())
    }
    fn rename(&self, _: &Path, _: &Path) -> io::Result<()> {
        Err(none())
    }
    fn copy(&self, _: &Path, _: &Path) -> io::Result<()> {
        Err(none())
    }
    fn space(&self, _: &Path) -> io::Result<(u64, u64)> {
        Err(none())
    }
}
