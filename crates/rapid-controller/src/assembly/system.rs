//! The one assembly path of every front end ([`assemble`]): PATHs (a module, a folder,
//! a `.pgf`, a backup, a manifest) and plain [`LoadOptions`] become a booted
//! [`Controller`], ready for its start. A module, a folder, a `.pgf` or a backup of
//! one task is a system of one task run alone (unless a client operates it); a system
//! of several tasks (SYS.cfg `CAB_TASKS`, a manifest's tasks) has every task read
//! from its own folder or list, loaded, configured and booted together.
//!
//! Nothing is printed: what the user should know (notes) and why the system cannot
//! start ([`AssemblyError`]) are handed back for the front end to say its way.

use std::net::Ipv4Addr;
use std::path::{Path, PathBuf};

use rapid_sema::system::{self, ConfigFile, TaskFacts, TaskProgram};
use rapid_sema::{Diagnostic, Options, Severity, SourceInput};
use rapid_vm::builtins::controller::{ControllerState, OpMode};
use rapid_vm::{load_in, LoadError};

use super::inputs::{self, Inputs};
use crate::boot::system::{self as boot, BootError, BootOptions, Booted, Stimulus};
use crate::{Controller, TaskSpec};

/// How the system is to be assembled, as the front end was asked (plain data: the
/// command line's types stay with the front end).
#[derive(Debug, Clone)]
pub struct LoadOptions {
    /// A client operates the program (`rapid serve`, `rapid dap`): the system is never
    /// a program alone, the tasks' checked programs are kept (record components of
    /// data are read and written through them), and the system as a whole is not
    /// checked again (as `rapid serve` has always booted).
    pub operated: bool,
    /// The first task's entry routine (`--entry`), above the configured one.
    pub entry: Option<String>,
    /// `--virtual-io`: names used as signals that the configuration lacks are virtual
    /// signals.
    pub virtual_io: bool,
    /// The operating mode and speed override every task starts with.
    pub state: ControllerState,
    /// The controller root of the file devices (`--home`), above the inputs' own.
    pub home: Option<PathBuf>,
    /// The robot model asked for (`--robot`), above every configured one.
    pub robot: Option<String>,
    /// The robots record every move (a trace or a report is asked for).
    pub record: bool,
    /// Cycles each NORMAL task runs (1: cycle mode; 0: continuous).
    pub cycles: u64,
    /// The bound on steps the front end ends the run at.
    pub max_steps: Option<u64>,
    /// Where the robots stand at the start, above the manifest's `start_joints`.
    pub start_joints: Option<[f64; 6]>,
    /// The stimulus file, read against the system's I/O configuration.
    pub stimulus: Option<PathBuf>,
    /// The controller's own address for the sockets (`--controller-ip`), above the
    /// manifest's `controller_ip`.
    pub controller_ip: Option<Ipv4Addr>,
}

impl Default for LoadOptions {
    /// `rapid run`'s defaults: automatic mode at 100 %, one cycle.
    fn default() -> Self {
        LoadOptions {
            operated: false,
            entry: None,
            virtual_io: false,
            state: ControllerState::new(OpMode::Auto, 100.0),
            home: None,
            robot: None,
            record: false,
            cycles: 1,
            max_steps: None,
            start_joints: None,
            stimulus: None,
            controller_ip: None,
        }
    }
}

/// What [`assemble`] found: the notes on how the inputs were read (a backup's module
/// left out), in the order found, and the system or why it cannot start.
pub struct Assembly {
    pub notes: Vec<String>,
    pub outcome: Result<Assembled, AssemblyError>,
}

/// A booted system, stopped before its power on.
pub struct Assembled {
    pub controller: Controller,
    /// One task without system inputs or outputs, not operated: a program run alone.
    pub alone: bool,
    /// The `n` of the robot ROB_n each task moves, by task; `None`: no robot.
    pub robots: Vec<Option<usize>>,
    /// What the user should know about the model that moves.
    pub model_note: Option<String>,
    /// Each task's inputs, in the controller's task order (their module files are the
    /// files the tasks' diagnostics, errors and saves refer to).
    pub inputs: Vec<Inputs>,
    /// The program-memory notes (W0706) `rapid check` gives, by task index into
    /// [`Assembled::inputs`]: a real controller may refuse such a program, so a front
    /// end says so before the run (the program still runs).
    pub program_memory: Vec<(usize, Diagnostic)>,
}

/// Why the system cannot start.
#[derive(Debug)]
pub enum AssemblyError {
    /// A PATH cannot be used at all (missing, unreadable, not a RAPID file): a tool
    /// failure, not a finding.
    Unreadable(inputs::InputError),
    /// The inputs' configuration has errors, or a `.pgf` entry does: what `rapid check`
    /// refuses (the inputs carry every finding, warnings too).
    Inputs(Box<Inputs>),
    /// `rapid check`'s findings about the system as a whole (a PERS declared
    /// differently, an event routine or entry routine missing); `diagnostics` index
    /// `files`.
    System { files: Vec<SourceInput>, diagnostics: Vec<Diagnostic> },
    /// A task's program cannot be loaded; `files` are its modules, which the error's
    /// places index.
    Load { task: String, alone: bool, error: Box<LoadError>, files: Vec<SourceInput> },
    /// The configuration around the tasks is refused, or a model is unknown.
    Boot(BootError),
}

impl AssemblyError {
    /// The error in one message (`rapid serve` says it so).
    pub fn message(&self) -> String {
        let first_error = |diagnostics: &[Diagnostic]| {
            let found = diagnostics.iter().find(|d| d.severity() == Severity::Error);
            let message = found.map_or("", |d| d.message.as_str());
            format!("the system has errors (`rapid check` shows them all): {message}")
        };
        match self {
            AssemblyError::Unreadable(e) => format!("{e:#}"),
            AssemblyError::Inputs(inputs) => first_error(&inputs.diagnostics),
            AssemblyError::System { diagnostics, .. } => first_error(diagnostics),
            AssemblyError::Load { task, error, .. } => {
                format!("task {task} cannot start: {error:?} (`rapid check` shows why)")
            }
            AssemblyError::Boot(
                BootError::Refused(message) | BootError::UnknownModel(message) | BootError::Internal(message),
            ) => message.clone(),
        }
    }
}

/// Reads PATHs, loads each task of the system they make, and boots it.
pub fn assemble(paths: &[PathBuf], options: &LoadOptions) -> Assembly {
    let mut notes = Vec::new();
    let outcome = assemble_noting(paths, options, &mut notes);
    Assembly { notes, outcome }
}

/// Whether the inputs' configuration has errors (the controller would not start), or a
/// `.pgf` entry does (the program is not whole): what `rapid check` refuses.
pub fn has_config_errors(inputs: &Inputs) -> bool {
    use rapid_sema::Code;
    let refused = |code| matches!(code, Code::ConfigFile | Code::ProgramFileEntry);
    inputs.diagnostics.iter().any(|d| refused(d.code) && d.severity() == Severity::Error)
}

/// One task's inputs and how it runs.
struct TaskInputs {
    inputs: Inputs,
    spec: TaskSpec,
}

fn assemble_noting(
    paths: &[PathBuf],
    options: &LoadOptions,
    notes: &mut Vec<String>,
) -> Result<Assembled, AssemblyError> {
    let first = inputs::collect(paths).map_err(AssemblyError::Unreadable)?;
    notes.extend(first.notes.iter().cloned());
    if has_config_errors(&first) {
        return Err(AssemblyError::Inputs(Box::new(first)));
    }
    // One task without system inputs or outputs: a program alone. Operated, the
    // program is started by a client: never alone.
    let alone = !options.operated && boot::is_alone(first.sys.as_ref(), &first.syspar);
    let name = first.task.as_ref().map_or("T_ROB1", |t| t.name.as_str()).to_owned();
    let entry = first.task.as_ref().and_then(|t| t.entry.clone());
    let sys = boot::system_of(first.sys.as_ref(), alone, &name, entry.as_deref());
    let specs = match &sys {
        Some(sys) if !alone => boot::task_specs(sys).map_err(|m| AssemblyError::Boot(BootError::Refused(m)))?,
        _ => vec![boot::alone_spec(&name)],
    };
    let tasks = collect_tasks(paths, specs, first, notes)?;
    // Every task's files in one table, as `rapid check` shows them: the first task's
    // inputs (with the configuration), then the other tasks' modules.
    let mut table = tasks[0].inputs.table();
    let mut offsets = vec![0];
    for task in &tasks[1..] {
        offsets.push(table.len());
        table.extend(task.inputs.modules.iter());
    }
    let owned_table = |table: &[&SourceInput]| table.iter().map(|&s| s.clone()).collect();
    let config = ConfigFile::of(tasks[0].inputs.sys_file, &table);
    let mut loaded = Vec::new();
    let mut facts: Vec<(TaskFacts, bool)> = Vec::new();
    let mut program_memory = Vec::new();
    for (idx, task) in tasks.iter().enumerate() {
        let configured = sys.as_ref().filter(|_| !alone).and_then(|sys| sys.task(&task.spec.name));
        let own_entry = task.inputs.task.as_ref().and_then(|t| t.entry.as_ref()).filter(|_| alone);
        let entry = match (&options.entry, configured, own_entry) {
            (Some(entry), _, _) if idx == 0 => entry.clone(),
            (_, Some(config), _) => config.entry.clone(),
            (_, _, Some(entry)) => entry.clone(),
            _ => "main".to_owned(),
        };
        let load_options = Options {
            predefined: task.inputs.predefined.clone(),
            virtual_signals: options.virtual_io,
            system_options: task.inputs.system_options.clone(),
            ..Options::default()
        };
        // The task as SYS.cfg or the manifest configures it (also for a task run alone):
        // where its entry routine is named.
        let declared = tasks[0].inputs.sys.as_ref().and_then(|sys| sys.task(&task.spec.name));
        let entry_given = idx == 0 && options.entry.is_some();
        let task_loaded = load_in(&task.inputs.modules, &entry, &load_options, crate::builtin_set::standard());
        let mut program = match (task_loaded, declared, config) {
            (Ok(program), _, _) => program,
            // Not started for want of its configured entry: `rapid check`'s finding, at
            // the configuration (`--entry` replaces the first task's).
            (Err(LoadError::NoEntry(_)), Some(declared), Some(config)) if !entry_given && !options.operated => {
                let diagnostics = vec![system::entry_finding(declared, config)];
                return Err(AssemblyError::System { files: owned_table(&table), diagnostics });
            }
            (Err(error), _, _) => {
                let files = task.inputs.modules.clone();
                let (task, error) = (task.spec.name.clone(), Box::new(error));
                return Err(AssemblyError::Load { task, alone, error, files });
            }
        };
        let too_big = program.warnings.iter().filter(|d| d.code == rapid_sema::Code::ProgramMemoryFull);
        program_memory.extend(too_big.map(|d| (idx, d.clone())));
        facts.push((program.analysis.as_deref().map(system::facts).unwrap_or_default(), entry_given));
        if !options.operated {
            // The checked program is not needed to run, and a run ends with its
            // process: its memory goes back to the system then, without the time
            // freeing it would take.
            std::mem::forget(program.analysis.take());
        }
        let home = options.home.clone().or_else(|| task.inputs.root.clone()).unwrap_or_else(|| default_home(paths));
        let syspar = task.inputs.syspar.clone();
        crate::boot::task::configure(&mut program, home, &task.inputs.modules, syspar, options.state.clone());
        loaded.push((task.spec.clone(), program));
    }
    // What `rapid check` finds about the system as a whole (persistents declared
    // differently, missing event routines) keeps it from starting.
    if !options.operated {
        let programs: Vec<TaskProgram<'_>> = tasks
            .iter()
            .zip(&offsets)
            .zip(&facts)
            .map(|((task, &file_offset), (facts, entry_given))| TaskProgram {
                name: &task.spec.name,
                file_offset,
                facts,
                entry_given: *entry_given,
            })
            .collect();
        let found = sys.as_ref().map(|sys| system::findings(sys, config, &programs)).unwrap_or_default();
        if !found.is_empty() {
            return Err(AssemblyError::System { files: owned_table(&table), diagnostics: found });
        }
    }
    let booted = boot_tasks(loaded, sys.as_ref(), &tasks, alone, options)?;
    let Booted { mut controller, robots, model_note } = booted;
    // `--controller-ip` wins over the manifest's `controller_ip`.
    if let Some(ip) = options.controller_ip.or(tasks[0].inputs.controller_ip) {
        for task in &mut controller.tasks {
            crate::bindings::sockets::of_mut(task.loaded.vm.resources_mut()).add_controller_addr(ip);
        }
    }
    let inputs = tasks.into_iter().map(|t| t.inputs).collect();
    Ok(Assembled { controller, alone, robots, model_note, inputs, program_memory })
}

/// Each task's inputs: the first PATH's reading serves the task it read, every other
/// task is read anew (a backup's other task folder, a manifest's other task).
fn collect_tasks(
    paths: &[PathBuf],
    specs: Vec<TaskSpec>,
    first: Inputs,
    notes: &mut Vec<String>,
) -> Result<Vec<TaskInputs>, AssemblyError> {
    let mut tasks: Vec<TaskInputs> = Vec::new();
    let mut first = Some(first);
    let mut own_findings = Vec::new();
    for spec in specs {
        let inputs = match first.take().filter(|f| f.task.as_ref().is_none_or(|t| t.name == spec.name)) {
            Some(inputs) => inputs,
            None => {
                let inputs = inputs::collect_task(paths, Some(&spec.name)).map_err(AssemblyError::Unreadable)?;
                notes.extend(inputs.notes.iter().cloned());
                // What is wrong for this task alone (a module of HOME it loads is missing).
                match tasks.first() {
                    Some(first) => own_findings.extend(inputs.task_config_findings(&first.inputs)),
                    None if has_config_errors(&inputs) => return Err(AssemblyError::Inputs(Box::new(inputs))),
                    None => {}
                }
                inputs
            }
        };
        let spec = TaskSpec { shared_files: inputs.shared_modules.clone(), ..spec };
        tasks.push(TaskInputs { inputs, spec });
    }
    if own_findings.iter().any(|d| d.severity() == Severity::Error) {
        let mut first = tasks.swap_remove(0).inputs;
        first.diagnostics.extend(own_findings);
        return Err(AssemblyError::Inputs(Box::new(first)));
    }
    Ok(tasks)
}

/// The loaded tasks booted into a controller, with the robots, units and conveyors
/// the first task's configuration describes and the stimulus read against its I/O.
fn boot_tasks(
    loaded: Vec<(TaskSpec, rapid_vm::Loaded)>,
    sys: Option<&rapid_config::sys::Sys>,
    tasks: &[TaskInputs],
    alone: bool,
    options: &LoadOptions,
) -> Result<Booted, AssemblyError> {
    let modules: Vec<SourceInput> = match options.virtual_io {
        true => tasks.iter().flat_map(|t| t.inputs.modules.iter().cloned()).collect(),
        false => Vec::new(),
    };
    let boot_options = BootOptions {
        alone,
        robot: options.robot.as_deref(),
        record: options.record,
        virtual_io: options.virtual_io.then_some(modules.as_slice()),
        cycles: options.cycles,
        max_steps: options.max_steps,
        auto: options.state.mode == OpMode::Auto,
    };
    let mut cell = tasks[0].inputs.cell();
    cell.start_joints = options.start_joints.or(cell.start_joints);
    let stimulus = options.stimulus.as_deref();
    boot::boot(loaded, sys, cell, &boot_options, &mut |io| read_stimulus(io, stimulus, alone))
        .map_err(AssemblyError::Boot)
}

/// The stimulus file, read against the system's I/O system `io`.
fn read_stimulus(
    io: Option<&rapid_io::IoSystem>,
    path: Option<&Path>,
    alone: bool,
) -> Result<Option<Stimulus>, String> {
    let Some(path) = path else { return Ok(None) };
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read the stimulus `{shown}`: {e}"))?;
    let Some(system) = io else {
        return Err(if alone {
            format!(
                "`{shown}`: a stimulus needs an I/O configuration (a backup with SYSPAR/EIO.cfg, or a manifest with `io`)"
            )
        } else {
            format!("`{shown}`: a stimulus needs an I/O configuration (the system has none: SYSPAR/EIO.cfg in a backup, `io` in a manifest)")
        });
    };
    super::stimulus::parse(&shown, &text, system).map(Some)
}

/// `rapid-controller` in the folder holding the first PATH (for a folder of modules,
/// beside that folder): the controller root when neither the front end nor the inputs
/// name one.
fn default_home(paths: &[PathBuf]) -> PathBuf {
    let first = paths.first().map(|p| p.as_path()).unwrap_or(Path::new("."));
    let parent = match first.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    parent.join("rapid-controller")
}
