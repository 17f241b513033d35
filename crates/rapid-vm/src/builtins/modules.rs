//! Loading, unloading and saving program modules while the task runs (§1.6, §1.17):
//! Load, UnLoad, StartLoad, WaitLoad, CancelLoad (`loadsession`), CheckProgRef, Save
//! and EraseModule.
//!
//! A built-in here only reads its arguments and, for a load, the module file; then it
//! leaves a [`ModuleRequest`] in [`ModuleState`]. Checking, compiling and linking code
//! into the task needs the whole VM, so `exec::modules` carries the request out as soon
//! as the built-in returns, before the next instruction runs.

use std::path::PathBuf;

use rapid_sema::SourceInput;
use rustc_hash::FxHashMap;

use super::{native, present, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Opaque, OpaqueState, Value};
use crate::world::devices;
use crate::world::FileKind;

type Res = Result<Option<Value>, RapidError>;

/// Module files bigger than this are refused: a module larger than the whole program
/// memory (the one table's figure, which `rapid check` measures a task's program
/// against) cannot fit, and reading a huge file would only stall the task.
const MAX_MODULE_BYTES: u64 = rapid_limits::PROGRAM_MEMORY_BYTES;

/// A module file read from a device, ready to be linked into the task.
#[derive(Debug, Clone)]
pub struct LoadFile {
    /// The RAPID path as the program wrote it (FilePath joined with \File).
    pub path: String,
    /// Where it is on the host, inside its device.
    pub host: PathBuf,
    pub source: SourceInput,
    /// `\Dynamic`: unloaded again at PP to Main.
    pub dynamic: bool,
}

/// What a built-in of this family asks the VM to do.
#[derive(Debug, Clone)]
pub enum ModuleRequest {
    Load {
        file: LoadFile,
        check_ref: bool,
    },
    Unload {
        host: PathBuf,
        path: String,
        err_if_changed: bool,
        save: bool,
    },
    /// WaitLoad: optionally unload one module, then link the one StartLoad read.
    WaitLoad {
        unload: Option<(PathBuf, String)>,
        file: LoadFile,
        check_ref: bool,
    },
    CheckProgRef,
    /// Save: `dest` is the file to write, `None` for the file the module came from.
    Save {
        module: String,
        dest: Option<(PathBuf, String)>,
    },
    Erase {
        module: String,
    },
}

/// The family's state: the request waiting for the VM and the open load sessions.
#[derive(Default)]
pub struct ModuleState {
    pub(crate) request: Option<ModuleRequest>,
    /// Load sessions StartLoad began and WaitLoad or CancelLoad has not ended.
    sessions: FxHashMap<u32, LoadFile>,
    last_session: u32,
}

impl ModuleState {
    /// PP to Main ends every load session (like files and sockets, they are task
    /// resources of the program run).
    pub fn close_all(&mut self) {
        self.sessions.clear();
        self.request = None;
    }

    /// The request left by the built-in that just ran.
    pub(crate) fn take_request(&mut self) -> Option<ModuleRequest> {
        self.request.take()
    }
}

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("Load", load),
        native("UnLoad", unload),
        native("StartLoad", start_load),
        native("WaitLoad", wait_load),
        native("CancelLoad", cancel_load),
        native("CheckProgRef", check_prog_ref),
        native("Save", save),
        native("EraseModule", erase_module),
    ],
};

/// An optional string argument.
fn opt_string(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<Option<String>, RapidError> {
    match arg {
        Some(a) if present(Some(a)) => ctx.string(a).map(Some),
        _ => Ok(None),
    }
}

/// FilePath with its optional \File, as one RAPID path, and where it is on the host.
fn resolve(ctx: &Ctx<'_>, path: &Value, file: Option<&Value>, err: Err) -> Result<(String, PathBuf), RapidError> {
    let path = ctx.string(path)?;
    let file = opt_string(ctx, file)?;
    let text = devices::join_object(&path, file.as_deref());
    match ctx.resources.devices.resolve(&text) {
        Ok(resolved) => Ok((text, resolved.path)),
        Err(fault) => Err(ctx.error(err, format!("`{text}`: {}", fault.message()))),
    }
}

/// Reads the module file named by FilePath and \File.
fn read_module(ctx: &Ctx<'_>, path: &Value, file: Option<&Value>, dynamic: bool) -> Result<LoadFile, RapidError> {
    let (path, host) = resolve(ctx, path, file, Err::FileNotFound)?;
    let fs = ctx.resources.devices.file_system();
    let meta = fs.metadata(&host);
    match meta {
        Ok(meta) if meta.kind == FileKind::File => {
            if meta.len > MAX_MODULE_BYTES {
                // ERR_PRGMEMFULL, "program memory full": Load's error for a module
                // that does not fit (the instructions manual's Load error list; real
                // programs' Load handlers test it beside ERR_IOERROR and ERR_SYNTAX).
                return Err(ctx.error(
                    Err::PrgMemFull,
                    format!("`{path}` is larger than the program memory ({MAX_MODULE_BYTES} bytes)"),
                ));
            }
        }
        // uncertain: the manual names ERR_FILNOTFND for a module file that is not there.
        _ => return Err(ctx.error(Err::FileNotFound, format!("the module file `{path}` was not found"))),
    }
    let bytes = fs.read(&host).map_err(|e| ctx.error(Err::IoError, format!("`{path}` cannot be read: {e}")))?;
    let source = SourceInput::from_bytes(path.clone(), bytes);
    Ok(LoadFile { path, host, source, dynamic })
}

/// A Load of the module file at RAPID path `text` (`HOME:/x.mod`) on the task's file
/// devices `files`, as a front end asks for it (RWS `loadmod`): the file read, checked
/// for size. Err says why not, as Load's error would.
pub fn front_end_load(files: &crate::world::devices::Devices, text: &str) -> Result<ModuleRequest, String> {
    let resolved = files.resolve(text).map_err(|fault| format!("`{text}`: {}", fault.message()))?;
    let host = resolved.path;
    let fs = files.file_system();
    match fs.metadata(&host) {
        Ok(meta) if meta.kind == FileKind::File && meta.len <= MAX_MODULE_BYTES => {}
        Ok(meta) if meta.kind == FileKind::File => {
            return Err(format!("`{text}` is larger than the program memory ({MAX_MODULE_BYTES} bytes)"))
        }
        _ => return Err(format!("the module file `{text}` was not found")),
    }
    let bytes = fs.read(&host).map_err(|e| format!("`{text}` cannot be read: {e}"))?;
    let source = SourceInput::from_bytes(text.to_owned(), bytes);
    let file = LoadFile { path: text.to_owned(), host, source, dynamic: false };
    Ok(ModuleRequest::Load { file, check_ref: false })
}

super::signature::layout! {
    static LOAD: LoadArgs = "Load" { dynamic: "Dynamic", file_path: "FilePath", file: "File", check_ref: "CheckRef" }
    static UNLOAD: UnloadArgs = "UnLoad" {
        err_if_changed: "ErrIfChanged", save: "Save", file_path: "FilePath", file: "File",
    }
    static START_LOAD: StartLoadArgs = "StartLoad" {
        dynamic: "Dynamic", file_path: "FilePath", file: "File", load_no: "LoadNo",
    }
    static WAIT_LOAD: WaitLoadArgs = "WaitLoad" {
        unload_path: "UnloadPath", unload_file: "UnloadFile", load_no: "LoadNo", check_ref: "CheckRef",
    }
    static SAVE: SaveArgs = "Save" { task_ref: "TaskRef", module_name: "ModuleName", file_path: "FilePath", file: "File" }
}

/// `Load [\Dynamic] FilePath [\File] [\CheckRef]`.
fn load(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *LOAD;
    let file = read_module(ctx, &args[at.file_path], args.get(at.file), present(args.get(at.dynamic)))?;
    ctx.resources.modules.request = Some(ModuleRequest::Load { file, check_ref: present(args.get(at.check_ref)) });
    Ok(None)
}

/// `UnLoad [\ErrIfChanged] | [\Save] FilePath [\File]`.
fn unload(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *UNLOAD;
    let (path, host) = resolve(ctx, &args[at.file_path], args.get(at.file), Err::Unload)?;
    let (err_if_changed, save) = (present(args.get(at.err_if_changed)), present(args.get(at.save)));
    ctx.resources.modules.request = Some(ModuleRequest::Unload { host, path, err_if_changed, save });
    Ok(None)
}

/// The session a loadsession argument holds, if any.
fn session_of(ctx: &Ctx<'_>, arg: &Value) -> Result<(Opaque, Option<u32>), RapidError> {
    ctx.handle_arg(arg, "a loadsession")
}

/// `StartLoad [\Dynamic] FilePath [\File] LoadNo`: the file is read now; WaitLoad links it.
fn start_load(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *START_LOAD;
    let (shell, handle) = session_of(ctx, &args[at.load_no])?;
    // uncertain: StartLoad on a session still waiting for its WaitLoad raises
    // ERR_LOADNO_INUSE (the name of that error says so; the manual's page is not public).
    if handle.is_some_and(|h| ctx.resources.modules.sessions.contains_key(&h)) {
        return Err(ctx.error(Err::LoadNoInUse, "the load session is in use; WaitLoad or CancelLoad it first"));
    }
    let file = read_module(ctx, &args[at.file_path], args.get(at.file), present(args.get(at.dynamic)))?;
    let state = &mut ctx.resources.modules;
    state.last_session = state.last_session.wrapping_add(1).max(1);
    let id = state.last_session;
    state.sessions.insert(id, file);
    ctx.store(&args[at.load_no], Value::Opaque(Box::new(Opaque { ty: shell.ty, state: OpaqueState::Handle(id) })))?;
    Ok(None)
}

/// Ends the session held in `arg` (the variable becomes unused) and returns its file.
fn end_session(ctx: &mut Ctx<'_>, arg: &Value, err: Err, what: &str) -> Result<LoadFile, RapidError> {
    let (shell, handle) = session_of(ctx, arg)?;
    let Some(file) = handle.and_then(|h| ctx.resources.modules.sessions.remove(&h)) else {
        return Err(ctx.error(err, format!("{what}: the loadsession has no load under way (no StartLoad)")));
    };
    ctx.store(arg, Value::Opaque(Box::new(Opaque { ty: shell.ty, state: OpaqueState::None })))?;
    Ok(file)
}

/// `WaitLoad [\UnloadPath] [\UnloadFile] LoadNo [\CheckRef]`.
fn wait_load(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *WAIT_LOAD;
    let unload = match args.get(at.unload_path) {
        Some(path) if present(Some(path)) => Some(resolve(ctx, path, args.get(at.unload_file), Err::Unload)?),
        _ => None,
    };
    let unload = unload.map(|(path, host)| (host, path));
    // uncertain: a loadsession with no StartLoad behind it raises ERR_UNKPROC in WaitLoad
    // (the catalogue's description of that error).
    let file = end_session(ctx, &args[at.load_no], Err::UnknownLoad, "WaitLoad")?;
    let check_ref = present(args.get(at.check_ref));
    ctx.resources.modules.request = Some(ModuleRequest::WaitLoad { unload, file, check_ref });
    Ok(None)
}

/// `CancelLoad LoadNo`: drops a load StartLoad began.
fn cancel_load(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    // uncertain: CancelLoad on a session not in use raises ERR_LOADNO_NOUSE.
    end_session(ctx, &args[0], Err::LoadNoNoUse, "CancelLoad")?;
    Ok(None)
}

/// `CheckProgRef`: ERR_LINKREF when the task has unresolved references.
fn check_prog_ref(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    ctx.resources.modules.request = Some(ModuleRequest::CheckProgRef);
    Ok(None)
}

/// `Save [\TaskRef] | [\TaskName] ModuleName [\FilePath] [\File]`.
fn save(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SAVE;
    // \TaskRef | \TaskName: `other_task` reads the pair from the first.
    let other = super::tasks::other_task(ctx, args, at.task_ref)?;
    let module = ctx.string(&args[at.module_name])?;
    let dest = match args.get(at.file_path) {
        Some(path) if present(Some(path)) => {
            let (text, host) = resolve(ctx, path, args.get(at.file), Err::IoError)?;
            Some((host, text))
        }
        // uncertain: \File without \FilePath names a file beside the module's own.
        _ => None,
    };
    if let Some(task) = other {
        // Another task saves its own module; this one waits for it (the controller).
        use super::tasks::{ask, Reply, Request};
        return match ask(ctx, Request::SaveModule { task, module, dest }) {
            Some(Reply::Failed(error)) => Err(*error),
            _ => Ok(None),
        };
    }
    ctx.resources.modules.request = Some(ModuleRequest::Save { module, dest });
    Ok(None)
}

/// `EraseModule ModuleName`.
fn erase_module(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let module = ctx.string(&args[0])?;
    ctx.resources.modules.request = Some(ModuleRequest::Erase { module });
    Ok(None)
}
