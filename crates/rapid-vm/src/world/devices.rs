//! Device paths and the sandbox: how a RAPID path such as `"HOME:/logs/a.txt"` becomes a
//! host path under the controller's root, and which paths are refused.
//!
//! Each device is a folder under the root named like the device (`HOME:` is
//! `<root>/HOME`), created the first time a path on it is used. A path without a device
//! is on `HOME:`. Names ignore letter case, as on the controller's disk. A path is
//! refused, never followed, when it names an unknown device, is an absolute host path,
//! climbs out of its device with `..`, or reaches through a symbolic link to somewhere
//! outside its device.
//!
//! The VM owns this mapping (device name → folder under the root) and the checks, not
//! the world's [`FileSystem`]: the sandbox is a rule of the controller, so it holds the
//! same for every embedder; the file system only sees the host paths it let through.
//! The root itself is configuration the controller gives ([`Devices::set_root`]).
//!
//! [`Devices`] is the task's part of this (the disk, the root, the files the loaded
//! modules came from): the language's own built-ins that name a path (Load, TextTabInstall,
//! SpyStart) and the embedder's file built-ins all resolve through it.

use std::path::{Path, PathBuf};

use crate::world::{FileKind, FileSystem};

/// The task's file devices: the world's disk they live on, the folder they live in,
/// and the loaded modules' files (ModExist, ModTimeDnum).
pub struct Devices {
    /// The world's disk (none until the embedder gives one: [`crate::Vm::set_world`]).
    fs: Box<dyn FileSystem>,
    root: Option<PathBuf>,
    modules: Vec<ModuleFile>,
}

/// A loaded module and the file it came from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ModuleFile {
    pub name: String,
    pub path: PathBuf,
}

impl Default for Devices {
    fn default() -> Devices {
        Devices { fs: Box::new(crate::world::NoFileSystem), root: None, modules: Vec::new() }
    }
}

impl Devices {
    /// The file system the devices live on.
    pub fn set_file_system(&mut self, fs: Box<dyn FileSystem>) {
        self.fs = fs;
    }

    pub fn file_system(&self) -> &dyn FileSystem {
        &*self.fs
    }

    /// Resolves RAPID path `text` on its device (see [`resolve`]).
    pub fn resolve(&self, text: &str) -> Result<Resolved, PathFault> {
        resolve(&*self.fs, self.root.as_deref(), text)
    }

    /// The folder the devices live in: `HOME:` is `<root>/HOME`, and so on. Without a
    /// root every path raises an error.
    pub fn set_root(&mut self, root: impl Into<PathBuf>) {
        self.root = Some(root.into());
    }

    pub fn root(&self) -> Option<&Path> {
        self.root.as_deref()
    }

    /// The task's loaded modules (ModExist, ModTimeDnum).
    pub fn set_modules(&mut self, modules: Vec<ModuleFile>) {
        self.modules = modules;
    }

    /// The task's loaded modules.
    pub fn modules(&self) -> &[ModuleFile] {
        &self.modules
    }
}

/// The file devices of an IRC5 controller (RobotWare 6) that the virtual controller
/// offers. `HOME:`, `TEMP:` and `RAMDISK:` are the ones ABB's manual and public
/// programs use; `BACKUP:` is the controller's backup folder.
// uncertain: the controller may know further names (removable disks such as `usb:`),
// which depend on the hardware; they are refused here as unknown devices.
pub const DEVICES: &[&str] = &["HOME", "TEMP", "RAMDISK", "BACKUP"];

/// The device of a path that names none (manual: a relative path is relative to the
/// program's home directory).
// uncertain: the manual's examples always give a device; HOME: is our default.
const DEFAULT_DEVICE: &str = "HOME";

/// Why a path cannot be used.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PathFault {
    /// No controller root was configured (the VM is used without `rapid run`).
    NoRoot,
    /// A serial channel (`com1:`, `pc:`), which the virtual controller has not.
    Serial(String),
    /// The path would leave its device, or names no device we have.
    Refused(String),
}

impl PathFault {
    pub fn message(&self) -> String {
        match self {
            PathFault::NoRoot => {
                "no controller root is configured for the file devices (rapid run --home DIR)".to_string()
            }
            PathFault::Serial(dev) => {
                format!("the serial channel `{dev}` is not available on the virtual controller")
            }
            PathFault::Refused(why) => why.clone(),
        }
    }
}

/// A RAPID path resolved to a host path inside its device.
#[derive(Debug, Clone)]
pub struct Resolved {
    pub path: PathBuf,
    /// The path is the device's own folder (`"HOME:"`).
    pub is_device_root: bool,
}

/// The Object of Open with its optional `\File`: `"HOME:"` and `"a.txt"` make
/// `"HOME:/a.txt"`; a File alone is relative to Object.
pub fn join_object(object: &str, file: Option<&str>) -> String {
    match file {
        None => object.to_string(),
        Some(file) if object.ends_with('/') || object.ends_with(':') => format!("{object}{file}"),
        Some(file) => format!("{object}/{file}"),
    }
}

/// Resolves `text` under `root` on `fs`, creating the device folder if it does not
/// exist yet.
pub fn resolve(fs: &dyn FileSystem, root: Option<&Path>, text: &str) -> Result<Resolved, PathFault> {
    let root = root.ok_or(PathFault::NoRoot)?;
    let (device, rest) = split_device(text)?;
    let segments = normalise(text, rest)?;
    let device_root = root.join(device);
    fs.create_dir_all(&device_root).map_err(|e| {
        PathFault::Refused(format!("the device folder `{}` cannot be made: {e}", device_root.display()))
    })?;
    let mut path = device_root.clone();
    for segment in &segments {
        let name = existing_spelling(fs, &path, segment);
        path.push(name);
    }
    check_links(fs, &device_root, &path, text)?;
    Ok(Resolved { path, is_device_root: segments.is_empty() })
}

/// The device a path names (canonical spelling) and the rest after `DEVICE:`.
fn split_device(text: &str) -> Result<(&'static str, &str), PathFault> {
    let Some(colon) = text.find(':') else {
        if text.starts_with('/') || text.starts_with('\\') {
            return Err(PathFault::Refused(format!("`{text}` is a host path; use a device such as HOME:")));
        }
        return Ok((DEFAULT_DEVICE, text));
    };
    let name = &text[..colon];
    let rest = &text[colon + 1..];
    if let Some(device) = DEVICES.iter().find(|d| d.eq_ignore_ascii_case(name)) {
        return Ok((device, rest));
    }
    if is_serial(name) {
        return Err(PathFault::Serial(format!("{name}:")));
    }
    Err(PathFault::Refused(format!("`{name}:` is not a device of the controller (HOME:, TEMP:, RAMDISK:, BACKUP:)")))
}

/// `com1:`..`com9:` and `pc:` are the controller's serial channels.
fn is_serial(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    lower == "pc" || lower.strip_prefix("com").is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}

/// The folders and file of `rest`, with `.` dropped and `..` applied; refused when a
/// `..` would climb above the device.
fn normalise<'a>(text: &str, rest: &'a str) -> Result<Vec<&'a str>, PathFault> {
    let mut segments = Vec::new();
    // Both separators split: a backslash is never part of a name on the controller.
    for segment in rest.split(['/', '\\']) {
        match segment {
            "" | "." => {}
            ".." => {
                if segments.pop().is_none() {
                    return Err(PathFault::Refused(format!("`{text}` climbs out of its device")));
                }
            }
            name => segments.push(name),
        }
    }
    Ok(segments)
}

/// The name of `segment` in `dir` as it is spelt on the disk: the controller's disk
/// ignores letter case (`LOG.TXT` opens `log.txt`), the host's may not. A name that
/// exists exactly, or nowhere, is kept as written.
// uncertain: we take the IRC5 mass storage to be a FAT-style file system that keeps
// but ignores letter case.
fn existing_spelling(fs: &dyn FileSystem, dir: &Path, segment: &str) -> String {
    if fs.symlink_metadata(&dir.join(segment)).is_ok() {
        return segment.to_string();
    }
    let Ok(entries) = fs.read_dir(dir) else { return segment.to_string() };
    let mut matches: Vec<String> = entries.into_iter().filter(|name| name.eq_ignore_ascii_case(segment)).collect();
    matches.sort();
    matches.into_iter().next().unwrap_or_else(|| segment.to_string())
}

/// Refuses a path that reaches, through a symbolic link, somewhere outside its device
/// (or through a link that leads nowhere, which a write would follow).
fn check_links(fs: &dyn FileSystem, device_root: &Path, path: &Path, text: &str) -> Result<(), PathFault> {
    let outside = || PathFault::Refused(format!("`{text}` leads outside its device through a link"));
    let Ok(device_canon) = fs.canonicalize(device_root) else { return Err(outside()) };
    for existing in path.ancestors() {
        let Ok(meta) = fs.symlink_metadata(existing) else { continue };
        if existing == device_root || !existing.starts_with(device_root) {
            return Ok(());
        }
        let canon = match fs.canonicalize(existing) {
            Ok(canon) => canon,
            Err(_) if meta.kind == FileKind::Symlink => return Err(outside()),
            Err(_) => return Ok(()),
        };
        return if canon.starts_with(&device_canon) { Ok(()) } else { Err(outside()) };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    // The sandbox on the host's disk (links included) is tested with the std world in
    // `rapid_controller::host_std`; here on a disk in memory.
    use super::*;
    use crate::world::memory::MemoryFs;

    #[test]
    fn devices_are_folders_under_the_root_and_names_ignore_case() {
        let fs = MemoryFs::new();
        let root = Path::new("/ctrl");
        fs.put("/ctrl/HOME/Logs/Day.txt", b"x");
        let r = resolve(&fs, Some(root), "home:/LOGS/day.TXT").unwrap();
        assert_eq!(r.path, Path::new("/ctrl/HOME/Logs/Day.txt"));
        let r = resolve(&fs, Some(root), "RAMDISK:").unwrap();
        assert!(r.is_device_root);
        assert!(fs.paths().contains(&PathBuf::from("/ctrl/RAMDISK")), "the device folder is made");
        assert!(matches!(resolve(&fs, Some(root), "HOME:/../x"), Err(PathFault::Refused(_))));
        assert_eq!(resolve(&fs, None, "HOME:a").unwrap_err(), PathFault::NoRoot);
    }
}
