//! Files and folders on the controller's devices (§1.16) and character/binary I/O on
//! them (§1.10), an extension of the interpreter ([`EXTENSION`]).
//!
//! * `folders`: MakeDir, RemoveDir, OpenDir/ReadDir/CloseDir (`dir`), RemoveFile,
//!   RenameFile, CopyFile, IsFile, FSSize, FileSize, FileTimeDnum, ModExist, ModTimeDnum.
//! * `iodev`: Open, Close, Rewind, ClearIOBuff and the open-file table (`iodev`).
//! * `io`: Write, ReadNum, ReadStr and the binary reads and writes.
//! * `text` and `anybin`: the pure parts (fields of text files, WriteAnyBin's format).
//!
//! The devices themselves (`HOME:` ... on the world's disk, the sandbox) are the
//! interpreter's (`rapid_vm::ext::devices`): the language's own Load and
//! TextTabInstall resolve paths there too. This family keeps what the task holds open.
//!
//! An iodev or dir variable holds `OpaqueState::Handle(n)`; `n` keys this family's tables
//! in [`FileState`]. Handles are never reused, so an iodev that was closed (or closed by
//! PP to Main) is simply not found: ERR_FILEACC.

mod anybin;
mod folders;
mod io;
mod iodev;
mod text;

use rustc_hash::FxHashMap;

use rapid_vm::ext::{
    devices, native, Ctx, Err, Extension, Family, Opaque, OpaqueState, RapidError, Resources, TaskHooks, TaskState,
    Value,
};

type Res = Result<Option<Value>, RapidError>;
/// An error before it becomes a RAPID error (the tables are borrowed while it is made).
type Fault = (Err, String);

/// The files and the directory listings the task holds open, in the task's extension
/// slot.
#[derive(Default)]
pub struct FileState {
    files: FxHashMap<u32, iodev::OpenFile>,
    dirs: FxHashMap<u32, folders::DirListing>,
    last_handle: u32,
}

impl FileState {
    /// Writes out what every open file holds in its write buffer. A failure stays
    /// pending and is reported by the file's next write or its Close.
    pub fn flush_all(&mut self) {
        for file in self.files.values_mut() {
            let _ = file.flush();
        }
    }

    fn new_handle(&mut self) -> u32 {
        self.last_handle = self.last_handle.wrapping_add(1).max(1);
        self.last_handle
    }
}

impl TaskState for FileState {
    /// Closes every open file and directory (end of program, PP to Main).
    fn close_all(&mut self) {
        self.files.clear();
        self.dirs.clear();
    }
}

/// The file built-ins, their per-task table, and the flush before a path is looked at.
pub static EXTENSION: Extension =
    Extension { name: "files", families: &[&FAMILY], hooks: Some(&FileHooks), init: Some(init) };

fn init(resources: &mut Resources) {
    resources.extensions.insert(FileState::default());
}

struct FileHooks;

impl TaskHooks for FileHooks {
    fn flush_files(&self, resources: &mut Resources) {
        if let Some(files) = resources.extensions.get_mut::<FileState>() {
            files.flush_all();
        }
    }
}

/// The task's open files and directories.
fn table<'a>(ctx: &'a mut Ctx<'_>) -> &'a mut FileState {
    ctx.resources.extensions.get_or_default::<FileState>()
}

static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("Open", iodev::open),
        native("Close", iodev::close),
        native("Rewind", iodev::rewind),
        native("ClearIOBuff", iodev::clear_io_buff),
        native("Write", io::write),
        native("ReadNum", io::read_num),
        native("ReadStr", io::read_str),
        native("ReadBin", io::read_bin),
        native("ReadStrBin", io::read_str_bin),
        native("WriteBin", io::write_bin),
        native("WriteStrBin", io::write_str_bin),
        native("WriteAnyBin", io::write_any_bin),
        native("ReadAnyBin", io::read_any_bin),
        native("WriteRawBytes", io::write_raw_bytes),
        native("ReadRawBytes", io::read_raw_bytes),
        native("MakeDir", folders::make_dir),
        native("RemoveDir", folders::remove_dir),
        native("OpenDir", folders::open_dir),
        native("ReadDir", folders::read_dir),
        native("CloseDir", folders::close_dir),
        native("RemoveFile", folders::remove_file),
        native("RenameFile", folders::rename_file),
        native("CopyFile", folders::copy_file),
        native("IsFile", folders::is_file),
        native("FSSize", folders::fs_size),
        native("FileSize", folders::file_size),
        native("FileTimeDnum", folders::file_time_dnum),
        native("ModExist", folders::mod_exist),
        native("ModTimeDnum", folders::mod_time_dnum),
    ],
};

// ---- helpers shared by the family ---------------------------------------------------------

/// The opaque shell of an iodev or dir argument and the handle it holds, if any.
fn handle_of(ctx: &Ctx<'_>, arg: &Value) -> Result<(Opaque, Option<u32>), RapidError> {
    ctx.handle_arg(arg, "an iodev or dir")
}

/// Stores `state` into the iodev or dir variable `arg`.
fn set_handle(ctx: &mut Ctx<'_>, arg: &Value, mut shell: Opaque, state: OpaqueState) -> Result<(), RapidError> {
    shell.state = state;
    ctx.store(arg, Value::Opaque(Box::new(shell)))
}

/// A RAPID path resolved on its device; `err` is the error a refused path raises here.
/// Every built-in that names a path comes here first, so what the task wrote but still
/// holds in its write buffers reaches the files before anything looks at them.
fn resolve(ctx: &mut Ctx<'_>, text: &str, err: Err) -> Result<devices::Resolved, RapidError> {
    ctx.resolve_path(text).map_err(|fault| ctx.error(err, fault.message()))
}

fn fault(ctx: &Ctx<'_>, (err, message): Fault) -> RapidError {
    ctx.error(err, message)
}

/// An I/O failure of the host as ERR_FILEACC, naming what was done.
fn io_fault(what: &str, e: &std::io::Error) -> Fault {
    (Err::FileAccess, format!("{what}: {e}"))
}

fn opt_string(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<Option<String>, RapidError> {
    match arg {
        None | Some(Value::Absent) => Ok(None),
        Some(v) => ctx.string(v).map(Some),
    }
}
