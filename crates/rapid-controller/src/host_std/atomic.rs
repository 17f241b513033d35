//! Replacing a file so that a crash, a kill or a power cut at any moment leaves either
//! its old or its new complete content, never a torn or empty file: the new bytes go
//! to a temporary file in the same folder, which is flushed to the disk (fsync) and
//! then renamed over the original (one atomic step of the file system); the folder is
//! flushed too, so the rename itself survives a power cut.
//!
//! The temporary file is `.NAME.PID-N.tmp`: hidden, and with an extension no loader
//! takes for a module. It is removed on every failure this process sees; only a kill
//! between its creation and the rename can leave one behind (nothing can clean up after
//! SIGKILL), and it is never read back. The next save of the same file removes such
//! leftovers once they are [`STALE_AFTER`] old (no save in progress takes that long).

use std::fs::{self, File, OpenOptions, Permissions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, SystemTime};

/// Attempts at finding a free temporary name before giving up (another process
/// writing the same file at the same instant, or leftovers of killed runs).
const MAX_NAME_TRIES: u32 = 64;

/// A temporary file of this file older than this is the leftover of a killed save.
pub const STALE_AFTER: Duration = Duration::from_secs(600);

/// Replaces the file at `path` with `bytes` atomically. An existing file keeps its
/// permissions (and, where the process may, its owner); a read-only file is refused
/// rather than silently replaced. A symbolic link is followed: the file it points to
/// is replaced and the link stays a link.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    write_atomic_with(path, |file| file.write_all(bytes))
}

/// [`write_atomic`] with the content written by `fill` (buffered), so a large output
/// need not be held in memory whole.
pub fn write_atomic_with(path: &Path, fill: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> io::Result<()> {
    let target = follow_link(path)?;
    let old = match fs::metadata(&target) {
        Ok(meta) if meta.is_file() => Some(meta),
        Ok(_) => return Err(io::Error::other(format!("`{}` is not a file", target.display()))),
        Err(e) if e.kind() == io::ErrorKind::NotFound => None,
        Err(e) => return Err(e),
    };
    if old.as_ref().is_some_and(|m| m.permissions().readonly()) {
        return Err(io::Error::new(io::ErrorKind::PermissionDenied, format!("`{}` is read-only", target.display())));
    }
    let dir = folder_of(&target);
    let name = target.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let (tmp, mut file) = create_temp(&dir, &name, old.as_ref().map(|m| m.permissions()))?;
    // From here on the guard removes the temporary file on any early return.
    let guard = TempGuard(Some(tmp));
    if let Some(meta) = &old {
        keep_permissions(&file, meta)?;
    }
    let mut buffered = io::BufWriter::with_capacity(1 << 16, &mut file);
    fill(&mut buffered)?;
    buffered.flush()?;
    drop(buffered);
    file.sync_all()?;
    drop(file);
    let tmp = guard.path();
    fs::rename(tmp, &target)?;
    guard.disarm();
    remove_stale_temps(&dir, &name);
    sync_folder(&dir)
}

/// Removes leftovers of killed saves of file `name` in `dir`: `.NAME.PID-N.tmp` files
/// not written for [`STALE_AFTER`]. Best effort: a leftover that stays is harmless.
fn remove_stale_temps(dir: &Path, name: &str) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    let prefix = format!(".{name}.");
    let now = SystemTime::now();
    for entry in entries.flatten() {
        let file_name = entry.file_name();
        let Some(rest) = file_name.to_str().and_then(|n| n.strip_prefix(&prefix)) else { continue };
        if !is_temp_suffix(rest) {
            continue;
        }
        let age = entry.metadata().ok().and_then(|m| m.modified().ok()).and_then(|t| now.duration_since(t).ok());
        if age.is_some_and(|age| age >= STALE_AFTER) {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Whether `rest` is `PID-N.tmp`, the end of our temporary names.
fn is_temp_suffix(rest: &str) -> bool {
    let Some((pid, n)) = rest.strip_suffix(".tmp").and_then(|r| r.split_once('-')) else { return false };
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    digits(pid) && digits(n)
}

/// The file a symbolic link points to (the path itself when it is no link).
fn follow_link(path: &Path) -> io::Result<PathBuf> {
    match fs::symlink_metadata(path) {
        Ok(meta) if meta.file_type().is_symlink() => fs::canonicalize(path),
        _ => Ok(path.to_path_buf()),
    }
}

fn folder_of(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Creates a fresh temporary file beside the target (never an existing one: a
/// leftover or another writer's file is not touched). On Unix it is created with the
/// original's mode, so the new content is never readable by more users than the old.
fn create_temp(dir: &Path, name: &str, perms: Option<Permissions>) -> io::Result<(PathBuf, File)> {
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    let pid = std::process::id();
    let mut last = None;
    for _ in 0..MAX_NAME_TRIES {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let tmp = dir.join(format!(".{name}.{pid}-{n}.tmp"));
        let mut options = OpenOptions::new();
        options.write(true).create_new(true);
        set_mode(&mut options, perms.as_ref());
        match options.open(&tmp) {
            Ok(file) => return Ok((tmp, file)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| io::Error::other("no free temporary file name")))
}

#[cfg(unix)]
fn set_mode(options: &mut OpenOptions, perms: Option<&Permissions>) {
    use std::os::unix::fs::{OpenOptionsExt, PermissionsExt};
    if let Some(perms) = perms {
        options.mode(perms.mode() & 0o7777);
    }
}

#[cfg(not(unix))]
fn set_mode(_options: &mut OpenOptions, _perms: Option<&Permissions>) {}

/// Gives the new file the old one's permission bits exactly (the creation mode above
/// is narrowed by the umask) and, best effort, its owner and group: a process that may
/// not change the owner (not root) writes files it owns anyway.
fn keep_permissions(file: &File, old: &fs::Metadata) -> io::Result<()> {
    file.set_permissions(old.permissions())?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let now = file.metadata()?;
        if now.uid() != old.uid() || now.gid() != old.gid() {
            // Not being allowed to is not a reason to lose the save.
            let _ = std::os::unix::fs::fchown(file, Some(old.uid()), Some(old.gid()));
        }
    }
    Ok(())
}

/// Flushes the folder's entry list, so the rename is on the disk. Some file systems
/// cannot flush a folder (EINVAL): the rename has happened; that is not a failure.
#[cfg(unix)]
fn sync_folder(dir: &Path) -> io::Result<()> {
    match File::open(dir).and_then(|d| d.sync_all()) {
        Err(e) if e.kind() == io::ErrorKind::InvalidInput || e.kind() == io::ErrorKind::Unsupported => Ok(()),
        other => other,
    }
}

/// Windows commits a rename (MoveFileEx with replace) without a folder flush; a
/// folder cannot be opened as a file there.
#[cfg(not(unix))]
fn sync_folder(_dir: &Path) -> io::Result<()> {
    Ok(())
}

/// Removes the temporary file when dropped, unless the rename took it.
struct TempGuard(Option<PathBuf>);

impl TempGuard {
    fn path(&self) -> &Path {
        self.0.as_deref().unwrap_or(Path::new(""))
    }

    fn disarm(mut self) {
        self.0 = None;
    }
}

impl Drop for TempGuard {
    fn drop(&mut self) {
        if let Some(path) = self.0.take() {
            let _ = fs::remove_file(path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rapid-atomic-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).expect("temp dir");
        dir
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> =
            fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    }

    #[test]
    fn replaces_and_creates_leaving_nothing_else() {
        let dir = temp_dir("plain");
        let file = dir.join("m.mod");
        write_atomic(&file, b"new file").unwrap();
        assert_eq!(fs::read(&file).unwrap(), b"new file");
        write_atomic(&file, b"second").unwrap();
        assert_eq!(fs::read(&file).unwrap(), b"second");
        assert_eq!(names(&dir), ["m.mod"]);
        fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn keeps_permissions_follows_links_and_refuses_read_only() {
        use std::os::unix::fs::PermissionsExt;
        let dir = temp_dir("perms");
        let file = dir.join("m.mod");
        fs::write(&file, b"old").unwrap();
        fs::set_permissions(&file, Permissions::from_mode(0o640)).unwrap();
        write_atomic(&file, b"new").unwrap();
        assert_eq!(fs::metadata(&file).unwrap().permissions().mode() & 0o7777, 0o640);
        // A link: the file behind it changes, the link stays.
        let link = dir.join("link.mod");
        std::os::unix::fs::symlink("m.mod", &link).unwrap();
        write_atomic(&link, b"through the link").unwrap();
        assert!(fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
        assert_eq!(fs::read(&file).unwrap(), b"through the link");
        // Read-only: refused, untouched, nothing left behind.
        fs::set_permissions(&file, Permissions::from_mode(0o444)).unwrap();
        let err = write_atomic(&file, b"no").unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::PermissionDenied);
        assert_eq!(fs::read(&file).unwrap(), b"through the link");
        assert_eq!(names(&dir), ["link.mod", "m.mod"]);
        fs::set_permissions(&file, Permissions::from_mode(0o644)).unwrap();
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn failures_leave_no_temporary_file() {
        let dir = temp_dir("fail");
        // The target is a folder: refused before anything is written.
        fs::create_dir(dir.join("sub.mod")).unwrap();
        assert!(write_atomic(&dir.join("sub.mod"), b"x").is_err());
        // A missing folder: the temporary file cannot even be made.
        assert!(write_atomic(&dir.join("missing").join("m.mod"), b"x").is_err());
        assert_eq!(names(&dir), ["sub.mod"]);
        // A failure after the temporary file was made (a failed write or rename):
        // the guard takes it away.
        let (tmp, _file) = create_temp(&dir, "m.mod", None).unwrap();
        assert!(tmp.exists());
        drop(TempGuard(Some(tmp.clone())));
        assert!(!tmp.exists());
        assert_eq!(names(&dir), ["sub.mod"]);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn old_leftovers_of_killed_saves_are_removed_by_the_next_save() {
        let dir = temp_dir("stale");
        let file = dir.join("m.mod");
        let make = |name: &str, age: Duration| {
            let f = File::create(dir.join(name)).unwrap();
            f.set_modified(SystemTime::now() - age).unwrap();
        };
        make(".m.mod.123-0.tmp", STALE_AFTER + Duration::from_secs(5));
        // Too young (maybe a save in progress), another file's, not ours: kept.
        make(".m.mod.124-0.tmp", Duration::from_secs(1));
        make(".x.mod.125-0.tmp", STALE_AFTER * 2);
        make(".m.mod.backup.tmp", STALE_AFTER * 2);
        write_atomic(&file, b"saved").unwrap();
        assert_eq!(names(&dir), [".m.mod.124-0.tmp", ".m.mod.backup.tmp", ".x.mod.125-0.tmp", "m.mod"]);
        fs::remove_dir_all(dir).unwrap();
    }
}
