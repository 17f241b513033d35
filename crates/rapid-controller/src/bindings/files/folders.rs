//! The file system built-ins (§1.16): MakeDir, RemoveDir, OpenDir, ReadDir, CloseDir
//! (`dir`), RemoveFile, RenameFile, CopyFile, IsFile, FSSize, FileSize, and the time
//! functions FileTimeDnum, ModExist, ModTimeDnum.
//!
//! Errors: a path that cannot be used (refused by the sandbox, missing, of the wrong
//! kind) raises ERR_FILEACC; RenameFile and CopyFile onto an existing file raise
//! ERR_FILEEXIST; a size beyond the integers a num holds exactly (8388608) raises
//! ERR_FILESIZE; ModTimeDnum of a module that is not loaded raises ERR_MOD_NOTLOADED.
// uncertain: the manual's error sections were not available to us word for word; where
// it may name ERR_FILNOTFND for a missing file we raise ERR_FILEACC.

use std::path::Path;
use std::time::SystemTime;

use rapid_vm::ext::{
    present, Ctx, Err, FileKind, FileMeta, FileSystem, OpaqueState, RapidError, Value, MAX_STRING_CHARS,
};

use super::{handle_of, resolve, set_handle, table, Res};

/// The largest integer a num holds exactly: sizes beyond it raise ERR_FILESIZE.
const NUM_INT_LIMIT: f64 = 8_388_608.0;

/// The entries of a directory opened with OpenDir, read one by one by ReadDir.
pub(super) struct DirListing {
    names: Vec<String>,
    next: usize,
}

/// A path argument resolved on its device (a refused path raises ERR_FILEACC).
fn path_arg(ctx: &mut Ctx<'_>, arg: &Value) -> Result<(String, std::path::PathBuf, bool), RapidError> {
    let text = ctx.string(arg)?;
    let resolved = resolve(ctx, &text, Err::FileAccess)?;
    Ok((text, resolved.path, resolved.is_device_root))
}

fn access(ctx: &Ctx<'_>, message: String) -> RapidError {
    ctx.error(Err::FileAccess, message)
}

fn fs<'a>(ctx: &'a Ctx<'_>) -> &'a dyn FileSystem {
    ctx.resources.devices.file_system()
}

/// What `path` is (links followed), if it exists: `Path::is_dir` and its kin, asked of
/// the world's file system.
fn kind_of(ctx: &Ctx<'_>, path: &Path) -> Option<FileKind> {
    fs(ctx).metadata(path).ok().map(|m| m.kind)
}

/// `MakeDir Path`: a new directory (its parent must exist).
pub(super) fn make_dir(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (text, path, _) = path_arg(ctx, &args[0])?;
    fs(ctx).create_dir(&path).map_err(|e| access(ctx, format!("the directory `{text}` cannot be made: {e}")))?;
    Ok(None)
}

/// `RemoveDir Path`: removes an empty directory (never a device itself).
pub(super) fn remove_dir(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (text, path, device) = path_arg(ctx, &args[0])?;
    if device {
        return Err(access(ctx, format!("`{text}` is a device; it cannot be removed")));
    }
    fs(ctx).remove_dir(&path).map_err(|e| access(ctx, format!("the directory `{text}` cannot be removed: {e}")))?;
    Ok(None)
}

/// `OpenDir Dev Path`: lists the directory for ReadDir.
///
/// The listing is taken when the directory is opened: "." and ".." first, as the
/// controller's file system lists them (a public RAPID program starts its entry count
/// at -2 for them), then the names in alphabetical order.
// uncertain: the controller lists names in the file system's order; we sort them so a
// program sees the same order on every host.
pub(super) fn open_dir(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (shell, _) = handle_of(ctx, &args[0])?;
    let (text, path, _) = path_arg(ctx, &args[1])?;
    let mut names = fs(ctx).read_dir(&path).map_err(|e| access(ctx, format!("`{text}` cannot be opened: {e}")))?;
    names.sort();
    names.splice(0..0, [".".to_string(), "..".to_string()]);
    let handle = table(ctx).new_handle();
    table(ctx).dirs.insert(handle, DirListing { names, next: 0 });
    set_handle(ctx, &args[0], shell, OpaqueState::Handle(handle))?;
    Ok(None)
}

/// `ReadDir(Dev FileName)`: TRUE and the next entry's name, or FALSE when none is left.
pub(super) fn read_dir(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, handle) = handle_of(ctx, &args[0])?;
    let listing = handle.and_then(|h| table(ctx).dirs.get_mut(&h));
    let Some(listing) = listing else { return Err(access(ctx, "the directory is not open".to_string())) };
    let Some(name) = listing.names.get(listing.next).cloned() else { return Ok(Some(Value::Bool(false))) };
    listing.next += 1;
    // Names are Latin-1 in RAPID; a host name with other characters shows them as `?`.
    let name: String = name.chars().map(|c| if u32::from(c) <= 0xFF { c } else { '?' }).collect();
    if name.chars().count() > MAX_STRING_CHARS {
        return Err(ctx.error(Err::StringTooLong, format!("the file name `{name}` is longer than 80 characters")));
    }
    ctx.store(&args[1], Value::Str(name.into()))?;
    Ok(Some(Value::Bool(true)))
}

/// `CloseDir Dev`.
pub(super) fn close_dir(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (shell, handle) = handle_of(ctx, &args[0])?;
    if let Some(h) = handle {
        table(ctx).dirs.remove(&h);
    }
    set_handle(ctx, &args[0], shell, OpaqueState::None)?;
    Ok(None)
}

/// `RemoveFile Path`: deletes a file (not a directory).
pub(super) fn remove_file(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (text, path, _) = path_arg(ctx, &args[0])?;
    if kind_of(ctx, &path) == Some(FileKind::Dir) {
        return Err(access(ctx, format!("`{text}` is a directory; use RemoveDir")));
    }
    fs(ctx).remove_file(&path).map_err(|e| access(ctx, format!("`{text}` cannot be removed: {e}")))?;
    Ok(None)
}

/// The source and target of RenameFile/CopyFile: the source must be an existing file
/// and the target must not exist (ERR_FILEEXIST).
fn source_and_target(
    ctx: &mut Ctx<'_>,
    args: &[Value],
) -> Result<(std::path::PathBuf, std::path::PathBuf), RapidError> {
    let (old_text, old, _) = path_arg(ctx, &args[0])?;
    let (new_text, new, _) = path_arg(ctx, &args[1])?;
    if kind_of(ctx, &old) != Some(FileKind::File) {
        return Err(access(ctx, format!("`{old_text}` is not an existing file")));
    }
    if kind_of(ctx, &new).is_some() {
        return Err(ctx.error(Err::FileExists, format!("`{new_text}` already exists")));
    }
    Ok((old, new))
}

/// `RenameFile OldPath NewPath`.
pub(super) fn rename_file(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (old, new) = source_and_target(ctx, args)?;
    fs(ctx).rename(&old, &new).map_err(|e| access(ctx, format!("the file cannot be renamed: {e}")))?;
    Ok(None)
}

/// `CopyFile OldPath NewPath`.
pub(super) fn copy_file(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (old, new) = source_and_target(ctx, args)?;
    fs(ctx).copy(&old, &new).map_err(|e| access(ctx, format!("the file cannot be copied: {e}")))?;
    Ok(None)
}

rapid_vm::ext::layout! {
    static IS_FILE: IsFileArgs = "IsFile" {
        directory: "Directory", fifo: "Fifo", reg_file: "RegFile", block_spec: "BlockSpec", char_spec: "CharSpec",
    }
    static FS_SIZE: FsSizeArgs = "FSSize" { total: "Total", kbyte: "Kbyte", mbyte: "Mbyte" }
    static FILE_TIME: FileTimeArgs = "FileTimeDnum" { access_time: "AccessTime", stat_c_time: "StatCTime", str_dig: "StrDig" }
}

/// `IsFile(Path [\Directory] | [\Fifo] | [\RegFile] | [\BlockSpec] | [\CharSpec])`:
/// whether the path exists, or, with a kind, whether it is of that kind.
///
/// A path that does not exist gives FALSE without a kind, and ERR_FILEACC with one:
/// public RAPID programs test `IsFile(dir \Directory)` and make the missing directory in
/// their ERR_FILEACC handler, while `IsFile(file)` alone answers FALSE for a new file.
pub(super) fn is_file(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *IS_FILE;
    let (text, path, _) = path_arg(ctx, &args[0])?;
    let kinds = [at.directory, at.fifo, at.reg_file, at.block_spec, at.char_spec];
    let kind_given = kinds.iter().any(|&k| present(args.get(k)));
    let meta = match fs(ctx).metadata(&path) {
        Ok(meta) => meta,
        Err(_) if !kind_given => return Ok(Some(Value::Bool(false))),
        Err(e) => return Err(access(ctx, format!("`{text}`: {e}"))),
    };
    let kind = meta.kind;
    let answer = if present(args.get(at.directory)) {
        kind == FileKind::Dir
    } else if present(args.get(at.fifo)) {
        kind == FileKind::Fifo
    } else if present(args.get(at.reg_file)) {
        kind == FileKind::File
    } else if present(args.get(at.block_spec)) {
        kind == FileKind::BlockDevice
    } else if present(args.get(at.char_spec)) {
        kind == FileKind::CharDevice
    } else {
        true
    };
    Ok(Some(Value::Bool(answer)))
}

/// A size in bytes as FSSize/FileSize return it: divided for `\Kbyte`/`\Mbyte` (whole
/// units, rounded down), ERR_FILESIZE beyond what a num holds exactly.
fn size_value(ctx: &Ctx<'_>, bytes: u64, divisor: u64) -> Res {
    let size = (bytes / divisor) as f64;
    if size > NUM_INT_LIMIT {
        return Err(ctx.error(Err::FileSize, format!("the size {size} is beyond 8388608; use \\Kbyte or \\Mbyte")));
    }
    Ok(Some(Value::Num(size as f32)))
}

/// `FSSize(Name [\Total] | [\Free] [\Kbyte] [\Mbyte])`: the total or free space of the
/// file system holding Name (free when neither is given).
// uncertain: the default when neither \Total nor \Free is given; we return the free space.
pub(super) fn fs_size(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (text, path, _) = path_arg(ctx, &args[0])?;
    if kind_of(ctx, &path).is_none() {
        return Err(access(ctx, format!("`{text}` does not exist")));
    }
    let (total, free) = fs(ctx).space(&path).map_err(|e| access(ctx, format!("the file system of `{text}`: {e}")))?;
    let at = *FS_SIZE;
    let bytes = if present(args.get(at.total)) { total } else { free };
    let divisor = if present(args.get(at.mbyte)) {
        1024 * 1024
    } else if present(args.get(at.kbyte)) {
        1024
    } else {
        1
    };
    size_value(ctx, bytes, divisor)
}

/// `FileSize(Path)`: the size of a file in bytes.
pub(super) fn file_size(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (text, path, _) = path_arg(ctx, &args[0])?;
    let meta = fs(ctx).metadata(&path).map_err(|e| access(ctx, format!("`{text}`: {e}")))?;
    size_value(ctx, meta.len, 1)
}

/// Seconds since 1970-01-01 00:00 UTC of a file time (whole seconds).
fn epoch_seconds(time: SystemTime) -> f64 {
    match time.duration_since(SystemTime::UNIX_EPOCH) {
        Ok(d) => d.as_secs() as f64,
        Err(e) => -(e.duration().as_secs() as f64),
    }
}

/// Stores the time in the optional `\StrDig` argument and returns it as a dnum.
fn time_result(ctx: &mut Ctx<'_>, seconds: f64, strdig: Option<&Value>) -> Res {
    if let Some(arg) = strdig.filter(|a| !a.is_absent()) {
        ctx.store(arg, Value::Str(format!("{seconds:.0}").into()))?;
    }
    Ok(Some(Value::Dnum(seconds)))
}

/// `FileTimeDnum(Path [\ModifyTime] | [\AccessTime] | [\StatCTime] [\StrDig])`: the
/// file's modification (default), access or status-change time, in seconds since 1970.
pub(super) fn file_time_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (text, path, _) = path_arg(ctx, &args[0])?;
    let meta = fs(ctx).metadata(&path).map_err(|e| access(ctx, format!("`{text}`: {e}")))?;
    let at = *FILE_TIME;
    let seconds = if present(args.get(at.access_time)) {
        meta.accessed
    } else if present(args.get(at.stat_c_time)) {
        meta.changed
    } else {
        meta.modified
    }
    .map(epoch_seconds)
    .ok_or_else(|| access(ctx, format!("`{text}`: {}", NO_TIME)))?;
    time_result(ctx, seconds, args.get(at.str_dig))
}

/// Why a file time is missing: the world's file system keeps no such time.
const NO_TIME: &str = "the file system keeps no such time for it";

/// The loaded module named `name` (any letter case).
fn module<'a>(ctx: &'a Ctx<'_>, name: &str) -> Option<&'a rapid_vm::ext::devices::ModuleFile> {
    ctx.resources.devices.modules().iter().find(|m| m.name.eq_ignore_ascii_case(name))
}

/// `ModExist(ModuleName)`: whether a module of that name is loaded in the task.
pub(super) fn mod_exist(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = ctx.string(&args[0])?;
    Ok(Some(Value::Bool(module(ctx, &name).is_some())))
}

/// `ModTimeDnum(Object [\StrDig])`: the modification time of the file the loaded
/// module was loaded from, in seconds since 1970.
pub(super) fn mod_time_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = ctx.string(&args[0])?;
    let Some(path) = module(ctx, &name).map(|m| m.path.clone()) else {
        return Err(ctx.error(Err::ModuleNotLoaded, format!("no module `{name}` is loaded")));
    };
    let seconds = fs(ctx)
        .metadata(&path)
        .and_then(|m: FileMeta| m.modified.ok_or_else(|| std::io::Error::other(NO_TIME)))
        .map(epoch_seconds)
        .map_err(|e| access(ctx, format!("the file of module `{name}`: {e}")))?;
    time_result(ctx, seconds, args.get(1))
}
