//! Program modules linked into and removed from a running task: what Load, UnLoad,
//! WaitLoad, EraseModule, Save and CheckProgRef ask for (§1.17; the built-ins that ask
//! are in `builtins::modules`).
//!
//! The task's program is kept as sources: the files it started with, then every module
//! loaded since, in load order. Linking a module checks that list again with the new
//! file last, so the module is checked against the task's global scope plus itself, and
//! compiles it (and the loaded modules, linked again) as the checker goes through them
//! (`compile::StreamCompiler::for_modules`): with the checker's resolution, and no
//! module's tree held whole. The checker numbers types, module-level data and routines in module order and
//! routine data after all of them; so with the new module last, everything that existed
//! keeps its number and the module's declarations get the next ones. Its global data
//! takes slots that the previous check gave to routine data, which the VM never keeps in
//! globals (routine data lives in frames), so no live slot is touched.
//!
//! Unloading leaves the module's numbers dead: from then on its place in the list is
//! taken by a stand-in module declaring as many LOCAL (unreachable) types, data and
//! routines, so the numbers of everything loaded after it hold. A dead global slot keeps
//! its last value and nothing reads it; a dead routine is `None` and late binding no
//! longer finds it.

use std::path::PathBuf;
use std::rc::Rc;

use rapid_sema::symbols::{DataKind, DeclOrigin, Def};
use rapid_sema::{Code as DiagCode, Diagnostic, Options, Program, Severity, SourceInput};
use rapid_syntax::ast::{Item, Module, RoutineKind};

use super::module_check::{check, Checked};
use super::{Exit, Unhandled, Vm};
use crate::builtins::modules::{LoadFile, ModuleRequest};
use crate::compile::{self, ModuleSource};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::ir::Code;
use crate::value::Value;
use crate::world::devices::ModuleFile;

/// Instructions a module's data initialisers may take (they are straight-line code).
const INIT_BUDGET: u64 = 1 << 32;
/// Diagnostics quoted in an ERR_SYNTAX or ERR_LINKREF message.
const QUOTED_DIAGNOSTICS: usize = 5;

/// The task's program as sources, and which of its modules are loaded.
#[derive(Default)]
pub struct TaskModules {
    /// The files the task started with (an erased module's text replaced by its stand-in).
    base: Vec<SourceInput>,
    /// The modules of `base`, in the checker's order.
    base_modules: Vec<BaseModule>,
    /// Modules loaded while running, in load order; unloaded ones stay as stand-ins.
    units: Vec<Unit>,
    /// How the task was checked (the configuration's signals): loaded modules see the
    /// same names.
    options: Options,
}

struct BaseModule {
    name: String,
    file: usize,
    /// Its position among the modules of its file.
    index: usize,
    live: bool,
}

struct Unit {
    name: String,
    /// The RAPID path it was loaded from, and that path on the host.
    path: String,
    host: PathBuf,
    /// Its text (its stand-in's once unloaded).
    source: SourceInput,
    live: bool,
    dynamic: bool,
    routines: Vec<u32>,
    datas: Vec<u32>,
    /// The slots of its persistents: a global PERS the task already had is shared.
    pers: Vec<u32>,
    init: Rc<Code>,
    /// Persistent values when loaded or last saved (UnLoad \ErrIfChanged).
    saved_pers: Vec<(u32, Value)>,
}

/// A name the checker could not resolve: a link error, not a syntax error.
fn is_unresolved(code: DiagCode) -> bool {
    matches!(code, DiagCode::UndefinedData | DiagCode::UndefinedFunction | DiagCode::UndefinedType)
        || code == DiagCode::UndefinedProcedure
}

/// `path:line:column: message` for the first few diagnostics.
fn quote(files: &[SourceInput], diags: &[&Diagnostic]) -> String {
    let mut parts: Vec<String> = diags
        .iter()
        .take(QUOTED_DIAGNOSTICS)
        .map(|d| match files.get(d.file) {
            Some(f) => {
                let at = rapid_syntax::LineIndex::new(&f.text).line_col(&f.text, d.span.start);
                format!("{}:{}:{}: {}", f.path, at.line, at.column, d.message)
            }
            None => d.message.clone(),
        })
        .collect();
    if diags.len() > QUOTED_DIAGNOSTICS {
        parts.push(format!("and {} more", diags.len() - QUOTED_DIAGNOSTICS));
    }
    parts.join("; ")
}

/// A module declaring as many types, module data and routines as `module`, all LOCAL
/// and named so nothing can reach them: it keeps the numbering of a removed module.
fn stand_in(module: &Module, serial: usize) -> String {
    let mut out = format!("MODULE zRemovedModule_{serial}(NOVIEW)\n");
    let (mut types, mut datas, mut routines) = (0, 0, 0);
    for item in &module.items {
        match item {
            Item::Type(_) => {
                out.push_str(&format!("LOCAL RECORD zRemovedType_{types}\n  num x;\nENDRECORD\n"));
                types += 1;
            }
            Item::Data(_) => {
                out.push_str(&format!("LOCAL VAR num zRemovedData_{datas};\n"));
                datas += 1;
            }
            Item::Routine(_) => {
                out.push_str(&format!("LOCAL PROC zRemovedRoutine_{routines}()\nENDPROC\n"));
                routines += 1;
            }
            Item::Placeholder(..) => {}
        }
    }
    out.push_str("ENDMODULE\n");
    out
}

/// The routines and module-level data module `module` declares.
fn members(prog: &Program, module: usize) -> (Vec<u32>, Vec<u32>) {
    let mine = |origin: DeclOrigin| matches!(origin, DeclOrigin::Module { module: m, .. } if m == module);
    let routines = prog.routines.iter().enumerate().filter(|(_, r)| mine(r.origin)).map(|(i, _)| i as u32).collect();
    let datas = prog.datas.iter().enumerate().filter(|(_, d)| mine(d.origin)).map(|(i, _)| i as u32).collect();
    (routines, datas)
}

/// Where the value of persistent `data` lives: a global PERS declared in several
/// modules is one persistent, held by the first declaration (what its name resolves
/// to); `None` when `data` is no persistent.
// uncertain: a module loaded with a global PERS the task already has keeps the current
// value (its own initial value is not applied), as for the task's own modules.
fn pers_slot(prog: &Program, data: u32) -> Option<u32> {
    let info = prog.datas.get(data as usize)?;
    if info.kind != DataKind::Pers {
        return None;
    }
    let sym = prog.interner.get(&info.display)?;
    if let DeclOrigin::Module { module, .. } = info.origin {
        if prog.scopes.module_locals.get(module).and_then(|m| m.get(&sym)) == Some(&Def::Data(data)) {
            return Some(data);
        }
    }
    match prog.scopes.globals.get(&sym).map(|o| o.def) {
        Some(Def::Data(first)) if prog.datas.get(first as usize).is_some_and(|d| d.kind == DataKind::Pers) => {
            Some(first)
        }
        _ => Some(data),
    }
}

/// Text as the controller's files hold it: Latin-1 (other characters become `?`).
fn latin1_bytes(text: &str) -> Vec<u8> {
    text.chars().map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?')).collect()
}

impl TaskModules {
    /// Remembers the files the task starts with.
    pub fn new(base: Vec<SourceInput>) -> TaskModules {
        let mut interner = rapid_syntax::Interner::default();
        let mut base_modules = Vec::new();
        for (file, input) in base.iter().enumerate().filter(|(_, f)| f.unreadable.is_none()) {
            // Only the module headers are needed: bodies are scanned over, not parsed.
            let parse = rapid_syntax::parse_outline(&input.text, &mut interner);
            for (index, module) in parse.file.modules.iter().enumerate() {
                let name = module.name.span.text(&input.text).to_string();
                base_modules.push(BaseModule { name, file, index, live: true });
            }
        }
        TaskModules { base, base_modules, units: Vec::new(), options: Options::default() }
    }

    /// Every source of the program as it stands.
    fn sources(&self) -> Vec<SourceInput> {
        self.base.iter().cloned().chain(self.units.iter().map(|u| u.source.clone())).collect()
    }

    /// Source file `file` (the task's files, then loaded modules).
    pub(super) fn source(&self, file: usize) -> Option<&SourceInput> {
        match self.base.get(file) {
            Some(input) => Some(input),
            None => self.units.get(file - self.base.len()).map(|u| &u.source),
        }
    }

    /// The text of source file `file`.
    pub(super) fn source_text(&self, file: usize) -> Option<&str> {
        self.source(file).map(|input| input.text.as_str())
    }

    /// Whether a module of this name is loaded (any letter case).
    fn is_loaded(&self, name: &str) -> bool {
        self.base_modules.iter().any(|m| m.live && m.name.eq_ignore_ascii_case(name))
            || self.units.iter().any(|u| u.live && u.name.eq_ignore_ascii_case(name))
    }
}

impl Vm {
    /// The names of the task's live modules, as they are written: the ones it started
    /// with, then those loaded since, in load order.
    pub fn module_names(&self) -> Vec<String> {
        let base = self.modules.base_modules.iter().filter(|m| m.live).map(|m| m.name.clone());
        base.chain(self.modules.units.iter().filter(|u| u.live).map(|u| u.name.clone())).collect()
    }

    /// Source file `file` of the running program: one it started with or a module it
    /// loaded since (for error locations).
    pub fn program_source(&self, file: usize) -> Option<&SourceInput> {
        self.modules.source(file)
    }

    /// The files the task was started with (for linking modules loaded at run time).
    pub fn set_program_sources(&mut self, files: Vec<SourceInput>) {
        self.modules = TaskModules::new(files);
    }

    /// How the task was checked, so modules loaded later are checked the same way.
    pub fn set_program_options(&mut self, options: Options) {
        self.modules.options = options;
    }

    /// Carries out a module request of a front end (RWS loading or unloading a module
    /// while the program is stopped): what the built-in would have asked for.
    pub fn front_end_module_request(
        &mut self,
        request: ModuleRequest,
        host: &mut dyn crate::host::Host,
    ) -> Result<(), RapidError> {
        self.module_request(request, host)
    }

    /// Carries out what a module built-in asked for.
    pub(super) fn module_request(
        &mut self,
        request: ModuleRequest,
        host: &mut dyn crate::host::Host,
    ) -> Result<(), RapidError> {
        if self.modules.base.is_empty() {
            // A VM made without `load` does not know its program's sources.
            return Err(RapidError::fatal(
                "this task was started without its program's sources; modules cannot be linked",
            ));
        }
        match request {
            ModuleRequest::Load { file, check_ref } => self.link(file, check_ref, host),
            ModuleRequest::Unload { host: path, path: text, err_if_changed, save } => {
                self.unload(&path, &text, err_if_changed, save)
            }
            ModuleRequest::WaitLoad { unload, file, check_ref } => {
                if let Some((path, text)) = unload {
                    self.unload(&path, &text, false, false)?;
                }
                self.link(file, check_ref, host)
            }
            ModuleRequest::CheckProgRef => self.check_prog_ref(),
            ModuleRequest::Save { module, dest } => self.save_module(&module, dest),
            ModuleRequest::Erase { module } => self.erase(&module),
        }
    }

    /// Checks, compiles and links `file` into the task, then initialises its data.
    fn link(&mut self, file: LoadFile, check_ref: bool, host: &mut dyn crate::host::Host) -> Result<(), RapidError> {
        let path = file.path.clone();
        if file.source.unreadable.is_some() {
            // uncertain: an encrypted module cannot be read here; the controller would load it.
            return Err(self.error(Err::IoError, format!("`{path}` is encrypted and cannot be loaded here")));
        }
        let mut interner = rapid_syntax::Interner::default();
        let parse = rapid_syntax::parse(&file.source.text, &mut interner);
        let [module] = &parse.file.modules[..] else {
            let n = parse.file.modules.len();
            return Err(self.error(Err::Syntax, format!("`{path}` holds {n} modules; a module file holds one")));
        };
        let name = module.name.span.text(&file.source.text).to_string();
        if self.modules.is_loaded(&name) {
            return Err(self.error(Err::Loaded, format!("a module named `{name}` is already loaded")));
        }
        if self.modules.units.iter().any(|u| u.live && u.host == file.host) {
            return Err(self.error(Err::Loaded, format!("`{path}` is already loaded")));
        }
        let mut files = self.modules.sources();
        files.push(file.source.clone());
        let new_file = files.len() - 1;
        let module_idx = self.modules.base_modules.len() + self.modules.units.len();
        // The new module, and the loaded ones linked again (`relink_units`).
        let mut wanted = self.live_unit_modules();
        wanted.push(module_idx);
        let builtins = self.builtins.clone();
        let mut checked = match check(files.clone(), &self.modules.options, Some((&builtins, &wanted))) {
            Ok(checked) => checked,
            Err(diags) => return Err(self.error(Err::Syntax, self.no_check(&name, &files, &diags, new_file))),
        };
        self.refuse_diagnostics(&name, &checked, new_file, check_ref)?;
        let mut streamed = std::mem::take(&mut checked.streamed);
        let modules = checked.modules();
        let compiled = compile::compile_module(&checked.prog, &modules, module_idx, &self.builtins, &mut streamed)
            .map_err(|errs| {
                let why: Vec<String> = errs.iter().take(QUOTED_DIAGNOSTICS).map(|e| e.message.clone()).collect();
                self.error(Err::Syntax, format!("module `{name}` cannot be run: {}", why.join("; ")))
            })?;
        let (routines, datas) = members(&checked.prog, module_idx);
        let pers = datas.iter().filter_map(|&d| pers_slot(&checked.prog, d)).collect();
        self.install(&checked.prog, compiled.routines, &compiled.defaults, &routines, &datas);
        let qualified = crate::qualified_procs(&checked.prog, &modules);
        self.procs_by_name.extend(qualified.into_iter().filter(|(_, idx)| routines.contains(idx)));
        self.relink_units(&checked, &modules, &mut streamed);
        let init = Rc::new(compiled.init);
        self.resources.devices.set_modules(
            self.resources
                .devices
                .modules()
                .iter()
                .cloned()
                .chain([ModuleFile { name: name.clone(), path: file.host.clone() }])
                .collect(),
        );
        self.modules.units.push(Unit {
            name,
            path,
            host: file.host,
            source: file.source,
            live: true,
            dynamic: file.dynamic,
            routines,
            datas,
            pers,
            init: init.clone(),
            saved_pers: Vec::new(),
        });
        self.refresh_symbols(Some(&checked));
        let res = self.run_init(init, host);
        let unit = self.modules.units.len() - 1;
        self.snapshot_pers(unit);
        res
    }

    /// Compiles the other loaded modules again: a name they use may now be declared by
    /// the new module (one unloaded and loaded again has new data slots). Frames already
    /// running keep the code they started with.
    fn relink_units(&mut self, checked: &Checked, modules: &[ModuleSource<'_>], streamed: &mut compile::Streamed) {
        for module in self.live_unit_modules() {
            let compiled = compile::compile_module(&checked.prog, modules, module, &self.builtins, streamed);
            let Ok(compiled) = compiled else {
                continue;
            };
            for (idx, code) in compiled.routines {
                if let Some(slot) = self.routines.get_mut(idx as usize) {
                    *slot = Some(Rc::new(code));
                }
            }
        }
    }

    /// The module indices (in the checker's order) of the modules loaded and still live.
    fn live_unit_modules(&self) -> Vec<usize> {
        let n_base = self.modules.base_modules.len();
        (0..self.modules.units.len()).filter(|&u| self.modules.units[u].live).map(|u| n_base + u).collect()
    }

    /// The ERR_SYNTAX message of a module the checker rejected outright.
    fn no_check(&self, name: &str, files: &[SourceInput], diags: &[Diagnostic], file: usize) -> String {
        let mine: Vec<&Diagnostic> =
            diags.iter().filter(|d| d.file == file && d.severity() == Severity::Error).collect();
        format!("module `{name}` does not check: {}", quote(files, &mine))
    }

    /// ERR_SYNTAX for a module that does not check, ERR_LINKREF for names that do not
    /// resolve (any unresolved reference in the task with `\CheckRef`).
    fn refuse_diagnostics(
        &self,
        name: &str,
        checked: &Checked,
        file: usize,
        check_ref: bool,
    ) -> Result<(), RapidError> {
        let errors: Vec<&Diagnostic> = checked.diagnostics.iter().filter(|d| d.severity() == Severity::Error).collect();
        let (mine, others): (Vec<&Diagnostic>, Vec<&Diagnostic>) = errors.iter().partition(|d| d.file == file);
        let syntax: Vec<&Diagnostic> = mine.iter().copied().filter(|d| !is_unresolved(d.code)).collect();
        // uncertain: a global name the task already declares (AmbiguousGlobal) is
        // reported as ERR_SYNTAX; the controller's error for that clash is not public.
        if !syntax.is_empty() {
            let why = quote(&checked.files, &syntax);
            return Err(self.error(Err::Syntax, format!("module `{name}` does not check: {why}")));
        }
        // uncertain: without \CheckRef the controller links a module with unresolved data
        // or functions and fails only when they are used; code that names what does not
        // exist cannot be compiled here, so that load is refused with ERR_LINKREF as well.
        // With \CheckRef the whole task is checked: also references other modules lost
        // (to an UnLoad or EraseModule) and procedure calls that reach nothing.
        let mut unresolved: Vec<&Diagnostic> = mine;
        if check_ref {
            unresolved.extend(others);
            unresolved.extend(checked.diagnostics.iter().filter(|d| d.code == DiagCode::UndefinedProcedure));
        }
        if unresolved.is_empty() {
            return Ok(());
        }
        let why = quote(&checked.files, &unresolved);
        Err(self.error(Err::LinkRef, format!("loading `{name}` leaves unresolved references: {why}")))
    }

    /// Puts compiled routines and new data in place.
    fn install(
        &mut self,
        prog: &Program,
        compiled: Vec<(u32, Code)>,
        defaults: &[(u32, Value)],
        routines: &[u32],
        datas: &[u32],
    ) {
        if self.routines.len() < prog.routines.len() {
            self.routines.resize(prog.routines.len(), None);
        }
        for (idx, code) in compiled {
            self.routines[idx as usize] = Some(Rc::new(code));
        }
        let n = prog.datas.len();
        self.storage.globals.grow(n);
        if let Some((_, init_defaults)) = self.init.as_mut() {
            grow(init_defaults, n);
            for (idx, value) in defaults {
                init_defaults[*idx as usize] = value.clone();
            }
        }
        for (idx, value) in defaults {
            if let Some(slot) = self.storage.globals.get_mut(*idx) {
                *slot = value.clone();
            }
        }
        if self.pers_globals.len() < n {
            self.pers_globals.resize(n, false);
        }
        for &idx in datas {
            let data = &prog.datas[idx as usize];
            self.pers_globals[idx as usize] = data.kind == DataKind::Pers;
            let named = crate::builtins::NamedData { global: idx, constant: data.kind == DataKind::Const };
            self.data_by_name.insert(data.display.to_lowercase(), named);
        }
        for &idx in routines {
            let info = &prog.routines[idx as usize];
            let global = prog
                .interner
                .get(&info.display)
                .and_then(|sym| prog.scopes.globals.get(&sym))
                .is_some_and(|o| o.def == Def::Routine(idx));
            if info.kind == RoutineKind::Proc && global {
                self.procs_by_name.insert(info.display.to_lowercase(), idx);
            }
        }
    }

    /// Runs a module's data initialisers on their own, the task's frames set aside.
    fn run_init(&mut self, init: Rc<Code>, host: &mut dyn crate::host::Host) -> Result<(), RapidError> {
        let frames = std::mem::take(&mut self.frames);
        let stack = std::mem::take(&mut self.storage.stack);
        self.push_frame(init, Vec::new());
        let exit = self.run(host, INIT_BUDGET);
        self.frames = frames;
        self.storage.stack = stack;
        match exit {
            Exit::Done => Ok(()),
            Exit::Unhandled(unhandled) => Err(unhandled.error),
            other => Err(RapidError::fatal(format!("a module's data initialisers ended with {other:?}"))),
        }
    }

    fn snapshot_pers(&mut self, unit: usize) {
        let Some(u) = self.modules.units.get(unit) else { return };
        let pers = u.pers.iter().filter_map(|&g| self.storage.globals.get(g).map(|v| (g, v.clone()))).collect();
        self.modules.units[unit].saved_pers = pers;
    }

    /// Whether a routine of `routines` is running (has a frame on the call chain).
    fn runs_any(&self, routines: &[u32]) -> bool {
        let codes: Vec<&Rc<Code>> =
            routines.iter().filter_map(|&r| self.routines.get(r as usize).and_then(|c| c.as_ref())).collect();
        self.frames.iter().any(|f| codes.iter().any(|c| Rc::ptr_eq(c, &f.code)))
    }

    /// Whether code of loaded module `unit` is running; its code is told by its file,
    /// since a frame may run code compiled before the module was linked again.
    fn unit_runs(&self, unit: usize) -> bool {
        let file = self.modules.base.len() + unit;
        self.frames.iter().any(|f| f.code.file == file) || self.runs_any(&self.modules.units[unit].routines)
    }

    /// `UnLoad`: removes the module loaded from `host`.
    fn unload(
        &mut self,
        host: &std::path::Path,
        text: &str,
        err_if_changed: bool,
        save: bool,
    ) -> Result<(), RapidError> {
        let Some(unit) = self.modules.units.iter().position(|u| u.live && u.host == host) else {
            // uncertain: a path no Load or WaitLoad loaded raises ERR_UNLOAD.
            return Err(self.error(Err::Unload, format!("no module was loaded from `{text}` with Load or WaitLoad")));
        };
        let u = &self.modules.units[unit];
        if self.unit_runs(unit) {
            let name = u.name.clone();
            return Err(self.error(Err::Unload, format!("module `{name}` cannot be unloaded: its code is running")));
        }
        if err_if_changed && self.unit_changed(unit) {
            let name = u.name.clone();
            // uncertain: "changed" is a persistent whose value differs from the file's.
            return Err(self.error(Err::NotSaved, format!("module `{name}` changed since it was loaded")));
        }
        // The manual: with \Save the module is saved, to where it was loaded from,
        // before it is unloaded (changed or not).
        if save {
            let name = self.modules.units[unit].name.clone();
            let dest = self.modules.units[unit].host.clone();
            self.save_module(&name, Some((dest, text.to_string())))?;
        }
        self.remove_unit(unit);
        Ok(())
    }

    fn unit_changed(&self, unit: usize) -> bool {
        self.modules.units[unit].saved_pers.iter().any(|(g, v)| self.storage.globals.get(*g) != Some(v))
    }

    /// Takes a loaded module out of the task: its routines, names and file entry.
    fn remove_unit(&mut self, unit: usize) {
        let u = &self.modules.units[unit];
        let (routines, datas, name) = (u.routines.clone(), u.datas.clone(), u.name.clone());
        let mut interner = rapid_syntax::Interner::default();
        let parse = rapid_syntax::parse(&u.source.text, &mut interner);
        let text = parse.file.modules.first().map_or_else(String::new, |m| stand_in(m, unit));
        let path = u.path.clone();
        let u = &mut self.modules.units[unit];
        u.source = SourceInput::from_text(path, text);
        u.live = false;
        self.forget(&routines, &datas, &name);
    }

    fn forget(&mut self, routines: &[u32], datas: &[u32], name: &str) {
        for &r in routines {
            self.procs_by_name.retain(|_, idx| *idx != r);
            if let Some(slot) = self.routines.get_mut(r as usize) {
                *slot = None;
            }
        }
        self.data_by_name.retain(|_, d| !datas.contains(&d.global));
        let files: Vec<ModuleFile> =
            self.resources.devices.modules().iter().filter(|m| !m.name.eq_ignore_ascii_case(name)).cloned().collect();
        self.resources.devices.set_modules(files);
        // Loaded modules compiled again without it: a call of one of its procedures then
        // raises ERR_REFUNKPRC, as a call of a procedure defined nowhere does. (Code
        // using its data no longer compiles and is kept; CheckProgRef reports it.)
        let (wanted, builtins) = (self.live_unit_modules(), self.builtins.clone());
        match check(self.modules.sources(), &self.modules.options, Some((&builtins, &wanted))) {
            Ok(mut checked) => {
                let mut streamed = std::mem::take(&mut checked.streamed);
                let modules = checked.modules();
                self.relink_units(&checked, &modules, &mut streamed);
                self.refresh_symbols(Some(&checked));
            }
            Err(_) => self.refresh_symbols(None),
        }
    }

    /// Makes the symbol catalogue (SetDataSearch, a front end's data by name) again
    /// from `checked`, the program as it now stands: the live modules' data, those
    /// loaded since the task started included. Unchecked, the unloaded ones' is dropped.
    fn refresh_symbols(&mut self, checked: Option<&Checked>) {
        let live = self.module_names();
        let fresh = checked.map(|c| crate::builtins::symsearch::catalog::task_symbols(&c.prog, &c.modules()));
        self.resources.symsearch.refresh(fresh, &live);
    }

    /// `EraseModule`: removes any module of the task by name.
    fn erase(&mut self, name: &str) -> Result<(), RapidError> {
        if let Some(unit) = self.modules.units.iter().position(|u| u.live && u.name.eq_ignore_ascii_case(name)) {
            if self.unit_runs(unit) {
                return Err(self.error(Err::Unload, format!("module `{name}` cannot be erased: its code is running")));
            }
            self.remove_unit(unit);
            return Ok(());
        }
        let Some(idx) = self.modules.base_modules.iter().position(|m| m.live && m.name.eq_ignore_ascii_case(name))
        else {
            // uncertain: erasing a module that is not in the task raises ERR_MODULE.
            return Err(self.error(Err::Module, format!("no module `{name}` is loaded")));
        };
        let checked = check(self.modules.sources(), &self.modules.options, None)
            .map_err(|_| self.error(Err::Module, "the task's program does not check"))?;
        let (routines, datas) = members(&checked.prog, idx);
        if self.runs_any(&routines) {
            return Err(self.error(Err::Unload, format!("module `{name}` cannot be erased: its code is running")));
        }
        let (file, index) = (self.modules.base_modules[idx].file, self.modules.base_modules[idx].index);
        let Some((_, parse)) = checked.parses.iter().find(|(f, _)| *f == file) else {
            return Err(self.error(Err::Module, format!("module `{name}` has no source")));
        };
        let Some(module) = parse.file.modules.get(index) else {
            return Err(self.error(Err::Module, format!("module `{name}` has no source")));
        };
        let text = &self.modules.base[file].text;
        let (start, end) = (module.span.start as usize, (module.span.end as usize).min(text.len()));
        let spliced = format!("{}{}{}", &text[..start], stand_in(module, 1_000_000 + idx), &text[end..]);
        self.modules.base[file].text = std::sync::Arc::new(spliced);
        self.modules.base_modules[idx].live = false;
        self.forget(&routines, &datas, name);
        Ok(())
    }

    /// `Save`: writes module `name` with its persistents' current values (§1.2.2: the
    /// initial value of a persistent is updated when its module is saved) to `dest`, or
    /// to the file it came from.
    /// Save of module `name` asked by another task (Save `\TaskName`), through the
    /// controller.
    pub fn save_module_for_another_task(
        &mut self,
        name: &str,
        dest: Option<(PathBuf, String)>,
    ) -> Result<(), RapidError> {
        self.save_module(name, dest)
    }

    /// The text of live module `name` as program memory holds it, current persistent
    /// values written in (what Save would write; RWS's module text). `None` when the
    /// task has no such module or its program does not check.
    pub fn module_text_now(&self, name: &str) -> Option<String> {
        let unit = self.modules.units.iter().position(|u| u.live && u.name.eq_ignore_ascii_case(name));
        let (file, index) = match unit {
            Some(unit) => (self.modules.base.len() + unit, 0),
            None => self
                .modules
                .base_modules
                .iter()
                .find(|m| m.live && m.name.eq_ignore_ascii_case(name))
                .map(|m| (m.file, m.index))?,
        };
        let checked = check(self.modules.sources(), &self.modules.options, None).ok()?;
        Some(self.module_text(&checked, file, index, unit.is_some()))
    }

    fn save_module(&mut self, name: &str, dest: Option<(PathBuf, String)>) -> Result<(), RapidError> {
        let n_base = self.modules.base.len();
        let unit = self.modules.units.iter().position(|u| u.live && u.name.eq_ignore_ascii_case(name));
        let (file, index, own) = match unit {
            Some(unit) => {
                let u = &self.modules.units[unit];
                (n_base + unit, 0, (u.host.clone(), u.path.clone()))
            }
            None => {
                let Some(m) = self.modules.base_modules.iter().find(|m| m.live && m.name.eq_ignore_ascii_case(name))
                else {
                    // uncertain: Save of a module not in the task raises ERR_MODULE.
                    return Err(self.error(Err::Module, format!("no module `{name}` is loaded")));
                };
                let file_name = std::path::Path::new(&self.modules.base[m.file].path)
                    .file_name()
                    .map_or_else(|| format!("{name}.mod"), |f| f.to_string_lossy().into_owned());
                // uncertain: the task's own modules came from the host, not a device; their
                // "own file" is taken to be the same name on HOME:.
                let text = format!("HOME:/{file_name}");
                let own = self
                    .resources
                    .devices
                    .resolve(&text)
                    .map_err(|f| self.error(Err::IoError, format!("`{text}`: {}", f.message())))?;
                (m.file, m.index, (own.path, text))
            }
        };
        let (host, shown) = dest.unwrap_or(own);
        let checked = check(self.modules.sources(), &self.modules.options, None)
            .map_err(|_| self.error(Err::IoError, "the task's program does not check"))?;
        let text = self.module_text(&checked, file, index, unit.is_some());
        self.resources
            .devices
            .file_system()
            .write_atomic(&host, &latin1_bytes(&text))
            .map_err(|e| self.error(Err::IoError, format!("module `{name}` cannot be saved to `{shown}`: {e}")))?;
        if let Some(unit) = unit {
            self.snapshot_pers(unit);
        }
        Ok(())
    }

    /// The text of module `index` of `file` with current persistent values written in
    /// (the whole file for a loaded module: one module per file, header comments kept).
    fn module_text(&self, checked: &Checked, file: usize, index: usize, whole_file: bool) -> String {
        let text = &checked.files[file].text;
        let Some(module) = checked.parses.iter().find(|(f, _)| *f == file).and_then(|(_, p)| p.file.modules.get(index))
        else {
            return text.as_str().to_owned();
        };
        let modules = checked.modules();
        let sites = crate::pers_sites(&checked.prog, &modules);
        let (start, end) = (module.span.start, module.span.end);
        let values: Vec<(&crate::persist::PersSite, &Value)> = sites
            .iter()
            .filter(|s| s.file == file && s.insert_at >= start && s.insert_at <= end)
            .filter_map(|s| {
                let slot = pers_slot(&checked.prog, s.global).unwrap_or(s.global);
                self.storage.globals.get(slot).map(|v| (s, v))
            })
            .collect();
        let new = crate::persist::rewrite(text, &values).unwrap_or_else(|| text.as_str().to_owned());
        if whole_file {
            return new;
        }
        let grown = new.len() as i64 - text.len() as i64;
        let end = usize::try_from(i64::from(end) + grown).unwrap_or(0);
        let mut out = new.get(start as usize..end).unwrap_or_default().to_string();
        out.push('\n');
        out
    }

    /// `CheckProgRef`: ERR_LINKREF when some reference of the task does not resolve.
    fn check_prog_ref(&mut self) -> Result<(), RapidError> {
        let files = self.modules.sources();
        let diags = match check(files.clone(), &self.modules.options, None) {
            Ok(checked) => checked.diagnostics,
            Err(diags) => diags,
        };
        let bad: Vec<&Diagnostic> = diags
            .iter()
            .filter(|d| d.severity() == Severity::Error || d.code == DiagCode::UndefinedProcedure)
            .collect();
        if bad.is_empty() {
            return Ok(());
        }
        Err(self.error(Err::LinkRef, format!("the task has unresolved references: {}", quote(&files, &bad))))
    }

    /// PP to Main: modules loaded `\Dynamic` are unloaded; the other loaded modules stay,
    /// their data initialised again like the task's own (§1.2.2 start-up table).
    pub(super) fn modules_at_pp_to_main(&mut self, host: &mut dyn crate::host::Host) -> Result<(), Unhandled> {
        for unit in 0..self.modules.units.len() {
            let u = &self.modules.units[unit];
            if !u.live {
                continue;
            }
            if u.dynamic {
                self.remove_unit(unit);
                continue;
            }
            let init = u.init.clone();
            if let Err(error) = self.run_init(init, host) {
                return Err(Unhandled { error, routine: "<load>".into(), file: usize::MAX, span: Default::default() });
            }
        }
        Ok(())
    }
}

/// Grows a slot vector to `n` (never shrinks: every slot given out stays).
fn grow(values: &mut Vec<Value>, n: usize) {
    if values.len() < n {
        values.resize(n, Value::Absent);
    }
}

#[cfg(test)]
#[path = "modules_tests.rs"]
mod tests;
