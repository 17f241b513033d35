//! rapid-vm: executes RAPID programs checked by rapid-sema.
//!
//! Invariant: no IO of its own. The pendant reaches it through the [`Host`] trait, the
//! file system, the network and the clocks through the [`world::World`] its embedder
//! gives each task (the std ones live in `rapid_controller::host_std`); the sandbox
//! of the file devices is the VM's own. It knows no configuration file format: the
//! controller hands it what it needs in the core's own terms (the task names of
//! `builtins::tasks`); multitasking is the crate rapid-tasks, the I/O signals the
//! crate rapid-signals, and the configuration data, the files, the sockets and the
//! RAPID Message Queue the controller's bindings (`rapid_controller::bindings`):
//! extensions that reach the interpreter through [`ext`]. It knows no I/O system (no rapid-io): signal
//! data is a handle an extension gave, and the loop asks the extension through
//! [`embed::TaskHooks`] (`read_signal`, `signal_changes`, `next_event`). RAPID call depth lives in explicit frames, never on
//! the Rust stack.
//!
//! What an embedder adds (built-in families, per-task state, the hooks the loop
//! calls) comes in through [`embed::Extension`] and a set of built-ins
//! ([`builtins::Builtins`]) handed to [`load_in`]. The interpreter core (`compile`,
//! `exec`, `ir`, `value`, `format`) must not know the robot: it asks it through
//! [`embed::TaskHooks`] only. The robot is the crate rapid-robot (`rapid_robot::EXTENSION`);
//! this crate knows none of its types and does not depend on rapid-motion. What an
//! extension's families use of the core is public on purpose: [`builtins::Ctx`] and
//! its argument readers (`arg_name`, `call_place`, `in_trap`, `instruction_here`),
//! [`builtins::Family`] with `builtins::native`, the catalogue argument layouts
//! ([`builtins::signature`], the `layout!` macro), and the task, interrupt and
//! waiting helpers of `builtins::tasks`, `builtins::interrupts` and
//! `builtins::wait`. Multitasking (sync points, semaphores, the tasks' kinds) is the
//! extension crate rapid-tasks; the core keeps of tasks only what its own built-ins
//! need (`builtins::tasks`).

pub mod builtins;
pub mod compile;
pub mod disas;
pub mod embed;
pub mod errnames;
pub mod error;
pub mod events;
pub mod exec;
pub mod ext;
pub mod format;
pub mod host;
pub mod instrs;
pub mod ir;
pub mod ops;
pub mod packed;
pub mod persist;
mod refusals;
pub mod value;
pub mod world;

use rapid_sema::symbols::{DeclOrigin, Def};
use rapid_sema::{Diagnostic, Options, Program, SourceInput};
use rapid_syntax::ast::RoutineKind;
use rustc_hash::FxHashMap;

pub use exec::backward::{BackStep, BackwardRefusal};
pub use exec::{ErrorStop, Exit, Unhandled, Vm};
pub use host::{Host, Prompt, PromptReply, RecordingHost};

/// Why a program could not be loaded.
#[derive(Debug)]
pub enum LoadError {
    /// The program does not check: its diagnostics (errors among them).
    Diagnostics(Vec<Diagnostic>),
    /// It checks, but uses something the interpreter cannot run yet.
    Unsupported(Vec<compile::CompileError>),
    /// No routine of that name to start.
    NoEntry(String),
    /// Giving data its initial values failed.
    Init(Unhandled),
}

/// A program ready to run: its VM positioned at the entry routine.
pub struct Loaded {
    pub vm: Vm,
    /// Warnings found while checking.
    pub warnings: Vec<Diagnostic>,
    /// Where each module-level persistent's value is written (for Save Module).
    pub persistents: Vec<persist::PersSite>,
    /// The entry routine (for [`Vm::pp_to_main`]).
    pub entry: u32,
    /// The global persistents other tasks share by name (§1.20).
    pub shared_pers: Vec<SharedPers>,
    /// Module-level variables (VAR) with their files: those of a module installed
    /// shared are one object for every task unless declared TASK VAR (§1.2.2).
    pub module_vars: Vec<ModuleVar>,
    /// The checked program the VM was compiled from. It is not needed to run; it is
    /// handed over so that a process about to exit can skip dropping it (a tenth of
    /// `rapid run`'s start-up goes to freeing the catalogue's declarations).
    pub analysis: Option<Box<Program>>,
    /// Every type of the program by lower-case name: values passed between tasks have
    /// their record types renumbered through it.
    pub types_by_name: FxHashMap<String, rapid_sema::types::TypeId>,
}

/// A module-level variable and the file its module is in.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ModuleVar {
    pub data: SharedPers,
    /// Index of the module's file among the files loaded.
    pub file: usize,
    /// Declared `TASK VAR`: every task has its own value.
    pub task_scoped: bool,
}

/// A module-level persistent declared neither LOCAL nor TASK: one object for every
/// task of the system that declares it (§1.20).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SharedPers {
    pub global: u32,
    /// As declared (compared without regard to case).
    pub name: String,
    pub type_name: String,
    /// Array sizes (all 0 for a scalar): tasks must agree on type and size.
    pub dims: [u32; 3],
    /// Declared with an initial value (a persistent may omit it, §1.2.2: it then takes
    /// the value another declaration gives it).
    pub initialised: bool,
}

/// Checks, compiles and initialises the task made of `files`, ready to run `entry`.
pub fn load(files: &[SourceInput], entry: &str) -> Result<Loaded, LoadError> {
    load_with(files, entry, &Options::default())
}

/// [`load`] with checking options: the data the system configuration declares (the
/// signals of a backup's `EIO.cfg`). It loads with the language's built-ins alone
/// ([`builtins::Builtins::core`]); a program that moves a robot loads through
/// [`load_in`] with a set that has the robot's extension (the controller's).
pub fn load_with(files: &[SourceInput], entry: &str, options: &Options) -> Result<Loaded, LoadError> {
    load_in(files, entry, options, builtins::Builtins::core())
}

/// [`load_with`] for the set of built-ins `builtins` (the core's and an embedder's
/// extensions, `embed`): calls are resolved in it, the task runs with it and its
/// extensions' state and hooks.
pub fn load_in(
    files: &[SourceInput],
    entry: &str,
    options: &Options,
    builtins: std::sync::Arc<builtins::Builtins>,
) -> Result<Loaded, LoadError> {
    // Each routine's body is parsed once, by the checker, and compiled as it is checked.
    let (mut prog, warnings, parses, streamed) = checked(files, options, &builtins)?;
    let modules = module_sources(files, &parses);
    let compiled = compile_modules(&mut prog, &modules, &builtins, streamed)?;
    let types = ops::OpTypes { pos: prog.core.pos, orient: prog.core.orient };
    let mut procs_by_name: FxHashMap<String, u32> = prog
        .routines
        .iter()
        .enumerate()
        .filter(|(_, r)| r.chapter.is_none() && r.kind == RoutineKind::Proc)
        .map(|(idx, r)| (r.display.to_lowercase(), idx as u32))
        .collect();
    procs_by_name.extend(qualified_procs(&prog, &modules));
    let global_named = |name: &str| match prog.interner.get(name).and_then(|sym| prog.scopes.builtins.get(&sym)) {
        Some(Def::Data(idx)) => Some(*idx),
        _ => None,
    };
    let errno_global = global_named("ERRNO");
    let mut vm = Vm::new(
        builtins,
        compiled.routines,
        procs_by_name,
        compiled.global_defaults.clone(),
        types,
        FxHashMap::default(),
        errno_global,
    );
    vm.set_intno_global(global_named("INTNO"));
    let mut host = RecordingHost::default();
    let init = std::rc::Rc::new(compiled.init);
    vm.set_init(init.clone(), compiled.global_defaults.clone());
    vm.start(init);
    if let Exit::Unhandled(unhandled) = vm.run(&mut host, u64::MAX) {
        return Err(LoadError::Init(unhandled));
    }
    let errnos: FxHashMap<&'static str, i32> = errnames::Err::ALL
        .iter()
        .map(|e| e.name())
        .chain(["LONG_JMP_ALL_ERR"])
        .filter_map(|name| {
            let value = vm.global(global_named(name)?)?.as_f64()?;
            Some((name, value as i32))
        })
        .collect();
    vm.set_errnos(errnos);
    let module_data = prog.datas.iter().enumerate().filter(|(_, d)| matches!(d.origin, DeclOrigin::Module { .. }));
    let named = |(i, d): (usize, &rapid_sema::symbols::DataInfo)| {
        let constant = d.kind == rapid_sema::symbols::DataKind::Const;
        (d.display.to_lowercase(), builtins::NamedData { global: i as u32, constant })
    };
    vm.set_data_names(module_data.map(named).collect());
    vm.resources_mut().symsearch = builtins::symsearch::catalog::task_symbols(&prog, &modules);
    let mut type_names = builtins::typenames::TypeNames::new(prog.types.named());
    type_names.templates = type_templates(&prog);
    vm.resources_mut().type_names = type_names;
    vm.extensions_loaded(&prog);
    vm.set_pers_globals(prog.datas.iter().map(|d| d.kind == rapid_sema::symbols::DataKind::Pers).collect());
    vm.set_program_sources(files.to_vec());
    vm.set_program_options(options.clone());
    let entry_idx = prog.interner.get(entry).and_then(|sym| prog.scopes.globals.get(&sym).map(|o| o.def));
    let started = match entry_idx {
        Some(Def::Routine(idx)) if prog.routines[idx as usize].kind == RoutineKind::Proc => vm.start_routine(idx),
        _ => false,
    };
    if !started {
        return Err(LoadError::NoEntry(entry.to_string()));
    }
    let entry_routine = match entry_idx {
        Some(Def::Routine(idx)) => idx,
        _ => 0,
    };
    vm.steps = 0;
    let persistents = pers_sites(&prog, &modules);
    let shared_pers = shared_pers(&prog, &modules);
    let module_vars = module_vars(&prog, &modules);
    let types_by_name = prog.types.named().map(|(id, name)| (name.to_ascii_lowercase(), id)).collect();
    let analysis = Some(Box::new(prog));
    Ok(Loaded { vm, warnings, persistents, entry: entry_routine, shared_pers, module_vars, types_by_name, analysis })
}

/// Checks and compiles the task made of `files` without running anything (not even
/// the data initialisers): its routines as the VM would run them, for listings
/// (`rapid dump-ir`, `disas::list`).
pub fn compile_files(
    files: &[SourceInput],
    options: &Options,
    builtins: std::sync::Arc<builtins::Builtins>,
) -> Result<CompiledTask, LoadError> {
    let (mut prog, _, parses, streamed) = checked(files, options, &builtins)?;
    let modules = module_sources(files, &parses);
    let compiled = compile_modules(&mut prog, &modules, &builtins, streamed)?;
    let global_names = prog.datas.iter().map(|d| d.display.clone()).collect();
    Ok(CompiledTask { compiled, global_names, builtins })
}

/// A task compiled for a listing: its code and the names of its globals (module and
/// predefined data, by the index `LoadGlobal` and the others name them with).
pub struct CompiledTask {
    pub compiled: compile::Compiled,
    pub global_names: Vec<String>,
    /// The built-ins its call sites name by id.
    pub builtins: std::sync::Arc<builtins::Builtins>,
}

/// The checked program with its warnings, the outline of every readable file (as the
/// checker parsed it) and the routines compiled while the checker went through their
/// bodies (with `builtins`), or the diagnostics that stop it from loading.
fn checked(
    files: &[SourceInput],
    options: &Options,
    builtins: &builtins::Builtins,
) -> Result<(Program, Vec<Diagnostic>, Outlines, compile::Streamed), LoadError> {
    let mut sink = compile::StreamCompiler::new(builtins, files);
    let analysis = rapid_sema::analyze_with(files, options, Some(&mut sink));
    let streamed = sink.finish();
    if Program::has_errors(&analysis.diagnostics) {
        return Err(LoadError::Diagnostics(analysis.diagnostics));
    }
    if let Some(refusal) = refusals::needs_encrypted(files, &analysis.diagnostics) {
        return Err(LoadError::Unsupported(vec![refusal]));
    }
    match analysis.program {
        Some(prog) => {
            let opaque = refusals::opaque_data(&prog);
            if !opaque.is_empty() {
                return Err(LoadError::Unsupported(opaque));
            }
            Ok((prog, analysis.diagnostics, indexed(analysis.outlines), streamed))
        }
        None => Err(LoadError::Diagnostics(analysis.diagnostics)),
    }
}

/// Each readable file's outline with the index of the file.
type Outlines = Vec<(usize, rapid_syntax::Parse)>;

/// The checker's outlines (one per file, `None` for an unreadable one) as
/// [`Outlines`].
fn indexed(outlines: Vec<Option<rapid_syntax::Parse>>) -> Outlines {
    outlines.into_iter().enumerate().filter_map(|(idx, parse)| parse.map(|parse| (idx, parse))).collect()
}

fn module_sources<'a>(
    files: &'a [SourceInput],
    parses: &'a [(usize, rapid_syntax::Parse)],
) -> Vec<compile::ModuleSource<'a>> {
    parses
        .iter()
        .flat_map(|(file, parse)| {
            parse.file.modules.iter().map(move |module| compile::ModuleSource {
                file: *file,
                text: &files[*file].text,
                module,
            })
        })
        .collect()
}

fn compile_modules(
    prog: &mut Program,
    modules: &[compile::ModuleSource<'_>],
    builtins: &builtins::Builtins,
    streamed: compile::Streamed,
) -> Result<compile::Compiled, LoadError> {
    let compiled = compile::compile(prog, modules, builtins, streamed);
    compiled.map_err(|errors| LoadError::Unsupported(refusals::one_per_option(errors)))
}

/// Late binding by `"module:procedure"` (public programs call loaded code as
/// `%"CfreePath:path"%`): every user procedure under its module-qualified name.
// uncertain: whether the controller also reaches a LOCAL procedure this way; we do.
pub(crate) fn qualified_procs(prog: &Program, modules: &[compile::ModuleSource<'_>]) -> Vec<(String, u32)> {
    let mut names = Vec::new();
    for (idx, routine) in prog.routines.iter().enumerate() {
        let DeclOrigin::Module { module, .. } = routine.origin else { continue };
        if routine.kind != RoutineKind::Proc {
            continue;
        }
        let Some(source) = modules.get(module) else { continue };
        let module_name = source.module.name.span.text(source.text);
        names.push((format!("{module_name}:{}", routine.display).to_lowercase(), idx as u32));
    }
    names
}

/// The module-level persistents and where their values stand in their files.
pub(crate) fn pers_sites(prog: &Program, modules: &[compile::ModuleSource<'_>]) -> Vec<persist::PersSite> {
    use rapid_sema::symbols::{DataKind, DeclOrigin};
    let mut sites = Vec::new();
    for (global, data) in prog.datas.iter().enumerate() {
        let DeclOrigin::Module { module, item } = data.origin else { continue };
        if data.kind != DataKind::Pers {
            continue;
        }
        let Some(source) = modules.get(module) else { continue };
        let Some(rapid_syntax::ast::Item::Data(decl)) = source.module.items.get(item) else { continue };
        let init = decl.init.map(|e| source.module.arena.expr(e).span);
        let semi = decl.span.text(source.text).rfind(';').map_or(decl.span.end, |i| decl.span.start + i as u32);
        sites.push(persist::PersSite { global: global as u32, file: source.file, init, insert_at: semi });
    }
    sites
}

/// The module-level persistents visible to other tasks (neither LOCAL nor TASK).
fn shared_pers(prog: &Program, modules: &[compile::ModuleSource<'_>]) -> Vec<SharedPers> {
    use rapid_sema::symbols::DataKind;
    let mut shared = Vec::new();
    for (global, data) in prog.datas.iter().enumerate() {
        let DeclOrigin::Module { module, item } = data.origin else { continue };
        let Some(source) = modules.get(module) else { continue };
        let Some(rapid_syntax::ast::Item::Data(decl)) = source.module.items.get(item) else { continue };
        if data.kind != DataKind::Pers || decl.scope != rapid_syntax::ast::DeclScope::Global {
            continue;
        }
        shared.push(SharedPers {
            global: global as u32,
            name: data.display.clone(),
            type_name: prog.types.name(data.ty).to_string(),
            dims: data.dims,
            initialised: decl.init.is_some(),
        });
    }
    shared
}

/// The module-level variables (VAR), with their files.
fn module_vars(prog: &Program, modules: &[compile::ModuleSource<'_>]) -> Vec<ModuleVar> {
    use rapid_sema::symbols::DataKind;
    let mut vars = Vec::new();
    for (global, data) in prog.datas.iter().enumerate() {
        let DeclOrigin::Module { module, item } = data.origin else { continue };
        let Some(source) = modules.get(module) else { continue };
        let Some(rapid_syntax::ast::Item::Data(decl)) = source.module.items.get(item) else { continue };
        if data.kind != DataKind::Var {
            continue;
        }
        let shared = SharedPers {
            global: global as u32,
            name: data.display.clone(),
            type_name: prog.types.name(data.ty).to_string(),
            dims: data.dims,
            initialised: true,
        };
        let task_scoped = decl.scope == rapid_syntax::ast::DeclScope::Task;
        vars.push(ModuleVar { data: shared, file: source.file, task_scoped });
    }
    vars
}

/// The value before anything is assigned of each declared or predefined record and
/// alias type (RMQ messages from outside the tasks are read into that shape).
fn type_templates(prog: &Program) -> FxHashMap<rapid_sema::types::TypeId, value::Value> {
    use rapid_sema::types::TypeKind;
    prog.types
        .named()
        .filter(|(id, _)| matches!(prog.types.info(*id).kind, TypeKind::Record(_) | TypeKind::Alias(_)))
        .map(|(id, _)| (id, compile::default_value(prog, id, &[])))
        .collect()
}
