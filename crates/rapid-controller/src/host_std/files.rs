//! The host's file system (`std::fs`) as the VM's [`FileSystem`].

use std::fs::{self, OpenOptions};
use std::io;
use std::path::{Path, PathBuf};

use rapid_vm::world::{FileKind, FileMeta, FileSystem, HostFile, OpenMode};

/// `std::fs` on the host paths the VM's sandbox hands it.
#[derive(Debug, Default, Clone, Copy)]
pub struct StdFs;

impl FileSystem for StdFs {
    fn open(&self, path: &Path, mode: OpenMode) -> io::Result<Box<dyn HostFile>> {
        let file = OpenOptions::new()
            .read(mode.read)
            .write(mode.write)
            .create(mode.create)
            .append(mode.append)
            .truncate(mode.truncate)
            .open(path)?;
        Ok(Box::new(file))
    }

    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        fs::read(path)
    }

    fn write_atomic(&self, path: &Path, bytes: &[u8]) -> io::Result<()> {
        super::atomic::write_atomic(path, bytes)
    }

    fn metadata(&self, path: &Path) -> io::Result<FileMeta> {
        fs::metadata(path).map(|m| meta(&m))
    }

    fn symlink_metadata(&self, path: &Path) -> io::Result<FileMeta> {
        fs::symlink_metadata(path).map(|m| meta(&m))
    }

    fn canonicalize(&self, path: &Path) -> io::Result<PathBuf> {
        path.canonicalize()
    }

    fn read_dir(&self, path: &Path) -> io::Result<Vec<String>> {
        let entries = fs::read_dir(path)?;
        Ok(entries.filter_map(|e| e.ok()).map(|e| e.file_name().to_string_lossy().into_owned()).collect())
    }

    fn create_dir(&self, path: &Path) -> io::Result<()> {
        fs::create_dir(path)
    }

    fn create_dir_all(&self, path: &Path) -> io::Result<()> {
        fs::create_dir_all(path)
    }

    fn remove_dir(&self, path: &Path) -> io::Result<()> {
        fs::remove_dir(path)
    }

    fn remove_file(&self, path: &Path) -> io::Result<()> {
        fs::remove_file(path)
    }

    fn rename(&self, from: &Path, to: &Path) -> io::Result<()> {
        fs::rename(from, to)
    }

    fn copy(&self, from: &Path, to: &Path) -> io::Result<()> {
        fs::copy(from, to).map(|_| ())
    }

    fn space(&self, path: &Path) -> io::Result<(u64, u64)> {
        space(path)
    }
}

/// What the VM reads of a path's metadata.
fn meta(m: &fs::Metadata) -> FileMeta {
    FileMeta {
        kind: kind(&m.file_type()),
        len: m.len(),
        modified: m.modified().ok(),
        accessed: m.accessed().ok(),
        changed: status_change(m),
    }
}

#[cfg(unix)]
fn kind(t: &fs::FileType) -> FileKind {
    use std::os::unix::fs::FileTypeExt;
    if t.is_symlink() {
        FileKind::Symlink
    } else if t.is_dir() {
        FileKind::Dir
    } else if t.is_file() {
        FileKind::File
    } else if t.is_fifo() {
        FileKind::Fifo
    } else if t.is_block_device() {
        FileKind::BlockDevice
    } else if t.is_char_device() {
        FileKind::CharDevice
    } else {
        FileKind::Other
    }
}

#[cfg(not(unix))]
fn kind(t: &fs::FileType) -> FileKind {
    if t.is_symlink() {
        FileKind::Symlink
    } else if t.is_dir() {
        FileKind::Dir
    } else if t.is_file() {
        FileKind::File
    } else {
        FileKind::Other
    }
}

/// The status-change time (ctime) in whole seconds.
#[cfg(unix)]
fn status_change(m: &fs::Metadata) -> Option<std::time::SystemTime> {
    use std::os::unix::fs::MetadataExt;
    let secs = m.ctime();
    let since = std::time::Duration::from_secs(secs.unsigned_abs());
    if secs >= 0 {
        std::time::UNIX_EPOCH.checked_add(since)
    } else {
        std::time::UNIX_EPOCH.checked_sub(since)
    }
}

#[cfg(not(unix))]
fn status_change(m: &fs::Metadata) -> Option<std::time::SystemTime> {
    m.modified().ok()
}

/// Total and free (available to the program) bytes of the file system holding `path`.
#[cfg(unix)]
fn space(path: &Path) -> io::Result<(u64, u64)> {
    let stat = rustix::fs::statvfs(path)?;
    Ok((stat.f_blocks.saturating_mul(stat.f_frsize), stat.f_bavail.saturating_mul(stat.f_frsize)))
}

#[cfg(not(unix))]
fn space(_: &Path) -> io::Result<(u64, u64)> {
    Err(io::Error::new(io::ErrorKind::Unsupported, "file system sizes are not available on this host"))
}

// The VM's sandbox (`rapid_vm::world::devices`) on the host's disk: the
// device folders, letter case and symbolic links as a real disk has them.
#[cfg(test)]
mod sandbox {
    use std::path::PathBuf;

    use rapid_vm::world::devices::{self, PathFault};

    use super::StdFs;

    /// The sandbox's resolution on the host's disk.
    fn resolve(root: Option<&std::path::Path>, text: &str) -> Result<devices::Resolved, PathFault> {
        devices::resolve(&StdFs, root, text)
    }

    fn temp_root(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rapid-devices-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn devices_map_to_folders() {
        let root = temp_root("map");
        let r = resolve(Some(&root), "HOME:/logs/a.txt").unwrap();
        assert_eq!(r.path, root.join("HOME").join("logs").join("a.txt"));
        assert!(!r.is_device_root);
        assert_eq!(resolve(Some(&root), "temp:x").unwrap().path, root.join("TEMP").join("x"));
        assert_eq!(resolve(Some(&root), "a/./b/../c").unwrap().path, root.join("HOME").join("a").join("c"));
        assert!(resolve(Some(&root), "RAMDISK:").unwrap().is_device_root);
        assert!(root.join("RAMDISK").is_dir());
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn letter_case_is_ignored() {
        let root = temp_root("case");
        std::fs::create_dir_all(root.join("HOME").join("Logs")).unwrap();
        std::fs::write(root.join("HOME").join("Logs").join("Day.txt"), "x").unwrap();
        let r = resolve(Some(&root), "HOME:/LOGS/day.TXT").unwrap();
        assert_eq!(r.path, root.join("HOME").join("Logs").join("Day.txt"));
        // A new name keeps the spelling it was given.
        let r = resolve(Some(&root), "home:/logs/New.txt").unwrap();
        assert_eq!(r.path, root.join("HOME").join("Logs").join("New.txt"));
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn escapes_are_refused() {
        let root = temp_root("escape");
        for bad in ["HOME:/../x", "..", "a/../../b", "/etc/passwd", "\\x", "C:/x", "FOO:x"] {
            assert!(matches!(resolve(Some(&root), bad), Err(PathFault::Refused(_))), "{bad}");
        }
        assert!(matches!(resolve(Some(&root), "com1:"), Err(PathFault::Serial(_))));
        assert_eq!(resolve(None, "HOME:a").unwrap_err(), PathFault::NoRoot);
        let _ = std::fs::remove_dir_all(&root);
    }

    #[cfg(unix)]
    #[test]
    fn links_out_of_the_device_are_refused() {
        let root = temp_root("links");
        let outside = temp_root("links-outside");
        std::fs::create_dir_all(root.join("HOME").join("inner")).unwrap();
        std::os::unix::fs::symlink(&outside, root.join("HOME").join("out")).unwrap();
        std::os::unix::fs::symlink(root.join("HOME").join("inner"), root.join("HOME").join("in")).unwrap();
        std::os::unix::fs::symlink(outside.join("nowhere"), root.join("HOME").join("dangling")).unwrap();
        assert!(matches!(resolve(Some(&root), "HOME:out/x.txt"), Err(PathFault::Refused(_))));
        assert!(matches!(resolve(Some(&root), "HOME:out"), Err(PathFault::Refused(_))));
        assert!(matches!(resolve(Some(&root), "HOME:dangling"), Err(PathFault::Refused(_))));
        assert!(resolve(Some(&root), "HOME:in/x.txt").is_ok());
        let _ = std::fs::remove_dir_all(&root);
        let _ = std::fs::remove_dir_all(&outside);
    }
}
