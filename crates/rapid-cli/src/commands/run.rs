//! `rapid run PATH…`: loads the task like `rapid check`, refuses a program with
//! errors, then runs the entry routine; pendant output goes to stdout, one line per
//! write, and an unhandled error is reported on stderr as the system error handler's
//! event-log entry would be.

// The CLI is the one crate that talks to the terminal; run reports on stderr.
#![allow(clippy::print_stderr)]

use std::io::{self, BufWriter, Write};

use rapid_sema::{Code, Diagnostic, Options, Severity, SourceInput};
use rapid_syntax::LineIndex;
use rapid_vm::builtins::files::ModuleFile;
use rapid_vm::{load_with, Exit, Host, LoadError};

use crate::args::RunArgs;
use crate::commands::system::{self, ConfigFile, TaskProgram};
use crate::commands::ExitStatus;
use crate::inputs;
use crate::render::{self, Files, Reported, Summary};

/// Instructions executed between checks of the bounds and of output flushing.
const SLICE: u64 = 1 << 16;

/// What `rapid run` says when the program executed WarmStart (the run ends there).
pub(crate) const WARM_START: &str =
    "warm start: the program requested a restart of the controller (WarmStart); the run ends here";

pub(crate) fn run(args: &RunArgs) -> anyhow::Result<ExitStatus> {
    let inputs = inputs::collect(&args.paths)?;
    print_notes(&inputs);
    if has_config_errors(&inputs) {
        return report_input_errors(&inputs);
    }
    // Several tasks, or system inputs and outputs (the controller operates the program
    // on their behalf), run under the controller.
    if inputs.sys.as_ref().is_some_and(|sys| sys.tasks.len() > 1) || super::run_system::has_system_signals(&inputs) {
        return super::run_system::run(args, inputs);
    }
    let entry = match (&args.entry, inputs.task.as_ref().and_then(|t| t.entry.as_ref())) {
        (Some(entry), _) | (None, Some(entry)) => entry.clone(),
        (None, None) => "main".to_owned(),
    };
    let options = Options { predefined: inputs.predefined.clone(), ..Options::default() };
    let mut loaded = match load_with(&inputs.modules, &entry, &options) {
        Ok(loaded) => loaded,
        Err(err) => return report_load_error(err, &inputs.modules),
    };
    let task_name = inputs.task.as_ref().map_or("T_ROB1", |t| t.name.as_str()).to_owned();
    // What `rapid check` finds about the configured system (an event routine the task
    // lacks) keeps it from starting, shown at the same place.
    if let Some(sys) = &inputs.sys {
        let facts = loaded.analysis.as_deref().map(system::facts).unwrap_or_default();
        let table = inputs.table();
        let task = TaskProgram { name: &task_name, file_offset: 0, facts: &facts };
        let found = system::findings(sys, ConfigFile::of(inputs.sys_file, &table), &[task]);
        if !found.is_empty() {
            return report_system_errors(&table, &found);
        }
    }
    // The checked program is not needed to run, and the process ends with the run: its
    // memory goes back to the system then, without the time freeing it would take.
    std::mem::forget(loaded.analysis.take());
    // A backup's (or a manifest's) own HOME folder is the controller's HOME: device.
    configure_files(&mut loaded, args, &inputs.modules, inputs.root.clone());
    // A socket wait polls, so that traps run while it waits (as during any wait), the
    // clock paced in wall-clock time meanwhile.
    loaded.vm.resources_mut().sockets.set_cooperative(true);
    loaded.vm.resources_mut().cfgdata.set_config(inputs.syspar.clone());
    loaded.vm.resources_mut().controller = args.controller_state();
    if let Err(message) = configure_io(&mut loaded, args, &inputs.syspar, &inputs.modules) {
        eprintln!("error: {message}");
        eprintln!("the system has errors; it was not run");
        return Ok(ExitStatus::Failure);
    }
    let (model, model_note) = match crate::motion_out::choose_model(args, inputs.robot.as_deref(), &inputs.syspar) {
        Ok(chosen) => chosen,
        Err(message) => {
            eprintln!("error: {message}");
            return Ok(ExitStatus::Error);
        }
    };
    crate::motion_out::configure(&mut loaded.vm.resources_mut().robot, model, args);
    // The task moves the robot its mechanical unit group names (ROB_1 without one).
    let number = crate::robots::of_single_task(&inputs);
    if let Err(message) = loaded.vm.resources_mut().tasking.shared.number_robots(vec![Some(number)]) {
        return Err(anyhow::anyhow!("internal error: {message}"));
    }
    let robot_name = format!("ROB_{number}");
    crate::motion_out::configure_base(&mut loaded.vm.resources_mut().robot, &inputs, number, &task_name);
    crate::motion_out::configure_ranges(&mut loaded.vm.resources_mut().robot, &inputs.syspar, number);
    crate::motion_out::configure_units(&mut loaded.vm.resources_mut().robot, &inputs.units, None, true);
    let resources = loaded.vm.resources_mut();
    let conveyors = &inputs.conveyors;
    if let Err(message) = crate::motion_out::configure_conveyors(
        &mut resources.robot,
        conveyors,
        resources.io.system.as_ref(),
        None,
        true,
    ) {
        eprintln!("error: {message}");
        eprintln!("the system has errors; it was not run");
        return Ok(ExitStatus::Failure);
    }
    let answers = pendant_answers(args)?;
    let mut host = StdoutHost { out: BufWriter::new(io::stdout().lock()), broken: false, answers };
    log_start(&mut loaded.vm, &task_name);
    // `rapid run` is power on and a start from main: the POWER_ON, then the START
    // event routines run first.
    for shelf in ["POWER_ON", "START"] {
        if let Err(failure) = run_hooks(&mut loaded, &mut host, inputs.sys.as_ref(), &task_name, shelf) {
            host.flush();
            return report_hook_failure(failure, &loaded, &inputs.modules);
        }
    }
    let mut cycles_run = 0u64;
    let mut pacer = crate::pace::Pacer::default();
    // The instructions executed when the clock was last charged for computing.
    let mut charged = loaded.vm.steps;
    let status = loop {
        if crate::interrupt::requested() {
            host.flush();
            eprintln!("{}", interrupted_at(loaded.vm.time));
            break ExitStatus::Interrupted;
        }
        // Defence in depth: an interpreter bug must not take the terminal down with a
        // panic trace; it is reported as what it is.
        let step = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| loaded.vm.run(&mut host, SLICE)));
        let Ok(exit) = step else {
            host.flush();
            eprintln!("internal error: the interpreter failed; please report this program");
            break ExitStatus::Error;
        };
        if let Some(max) = args.max_steps {
            if loaded.vm.steps > max {
                host.flush();
                eprintln!("error: stopped after {max} steps (--max-steps); the program did not end");
                break ExitStatus::Failure;
            }
        }
        match exit {
            // One cycle is run: ExitCycle ends it like the end of main.
            Exit::Stopped => {
                // The STOP event routines run when the program stops.
                if let Err(failure) = run_hooks(&mut loaded, &mut host, inputs.sys.as_ref(), &task_name, "STOP") {
                    host.flush();
                    return report_hook_failure(failure, &loaded, &inputs.modules);
                }
                break ExitStatus::Success;
            }
            Exit::Done | Exit::CycleEnded => {
                // Continuous run mode: the next cycle starts at the entry routine, the
                // data keeping its values. EXIT ends the program for good (§1.12: it
                // terminates execution where a restart is not allowed).
                cycles_run += 1;
                if (args.cycles != 0 && cycles_run >= args.cycles) || loaded.vm.ended_by_exit() {
                    if args.cycles == 1 && exit == Exit::CycleEnded {
                        host.flush();
                        eprintln!("{}", exit_cycle_note("the cycle"));
                    }
                    break ExitStatus::Success;
                }
                let steps = loaded.vm.steps;
                loaded.vm.time += computed(&mut charged, steps);
                let entry = loaded.entry;
                loaded.vm.start_routine(entry);
                if past_max_time(loaded.vm.time, args, &mut host) {
                    break ExitStatus::Failure;
                }
            }
            // Computing without waiting (a whole slice of a loop polling a flag a trap
            // sets): the clock moves on by the instructions' nominal time, as the system's
            // scheduler moves it, so timers come and --max-time bounds the loop. What is
            // computed before a wait takes no time (the hand-worked times stay exact).
            Exit::Budget | Exit::Wait(_) => {
                let steps = loaded.vm.steps;
                let seconds = match exit {
                    Exit::Wait(seconds) => {
                        charged = steps;
                        seconds
                    }
                    _ => computed(&mut charged, steps),
                };
                // With a socket open the clock runs in wall-clock time (a peer sees it).
                let paced = args.realtime || loaded.vm.resources().sockets.is_open();
                if paced {
                    host.flush();
                }
                let from = loaded.vm.time;
                loaded.vm.time = pacer.wait(paced, from, from + seconds, args.max_time.unwrap_or(f64::INFINITY));
                if past_max_time(loaded.vm.time, args, &mut host) {
                    break ExitStatus::Failure;
                }
            }
            Exit::Unhandled(unhandled) => {
                host.flush();
                // A module loaded at run time is not among the inputs; the VM knows it.
                let loaded_module = loaded.vm.program_source(unhandled.file);
                let (path, line, column) = match inputs.modules.get(unhandled.file).or(loaded_module) {
                    Some(input) => location(std::slice::from_ref(input), 0, unhandled.span.start),
                    None => location(&[], 0, 0),
                };
                eprintln!("error: {}", unhandled.error);
                eprintln!("  in routine {} at {path}:{line}:{column}", unhandled.routine);
                eprintln!("  the program stopped (no ERROR handler handled the error)");
                break ExitStatus::Failure;
            }
        }
    };
    host.flush();
    log_stop(&mut loaded.vm, &task_name, status);
    let program_end = loaded.vm.time;
    let resources = loaded.vm.resources_mut();
    let who = (task_name.as_str(), Some(robot_name.as_str()));
    let cycle = crate::motion_out::finish(resources, program_end, who, model_note.as_deref(), args)?;
    // The last fly-by point, if the program ended on one, became a stop point.
    loaded.vm.log_corner_failures();
    // The run is over: the robot leaves the task for the trace and the report.
    let robot = std::mem::take(&mut loaded.vm.resources_mut().robot);
    let sources = |file: usize| inputs.modules.get(file).or_else(|| loaded.vm.program_source(file));
    let outputs = crate::motion_out::RunOutputs {
        robot: &robot,
        sources: &sources,
        io: loaded.vm.io_system(),
        program: crate::motion_out::program_name(args),
        task: &task_name,
        robot_name: Some(&robot_name),
        cycle,
    };
    crate::motion_out::write_outputs(&outputs, args)?;
    // The recorded path (every planned move of the run) goes back to the system when
    // the process ends, without the time freeing it piece by piece would take.
    std::mem::forget(robot);
    if loaded.vm.resources_mut().controller.warm_start {
        eprintln!("{WARM_START}");
    }
    if args.event_log {
        for event in loaded.vm.event_log() {
            eprintln!("event {event}");
        }
    }
    // Both are written even when the other fails: neither may cost the other.
    let saved = if args.save_pers { crate::save::save_persistents(&loaded, &inputs.modules) } else { Ok(()) };
    let logged = args.elog.as_deref().map_or(Ok(()), |path| {
        let task = crate::elog::TaskEvents { task: crate::elog::MAIN_TASK, vm: &loaded.vm, files: &inputs.modules };
        crate::elog::write(path, &[task])
    });
    saved?;
    logged?;
    if let Some(path) = &args.io_log {
        write_io_log(loaded.vm.io_system(), path)?;
    }
    Ok(status)
}

/// The event log's entries for a start from main: the program pointer reset, the
/// program started.
pub(crate) fn log_start(vm: &mut rapid_vm::Vm, task: &str) {
    use rapid_vm::events::{PP_RESET, PROGRAM_STARTED};
    vm.log_state(PP_RESET, format!("The program pointer of task {task} was set to its entry routine."));
    vm.log_state(PROGRAM_STARTED, format!("Program execution in task {task} has been started."));
}

/// The event log's entry for the program's stop, with why it stopped.
pub(crate) fn log_stop(vm: &mut rapid_vm::Vm, task: &str, status: ExitStatus) {
    let why = match status {
        ExitStatus::Success => "the program ended",
        _ => "an error or a bound of the run stopped it",
    };
    vm.log_state(rapid_vm::events::PROGRAM_STOPPED, format!("Program execution in task {task} has stopped: {why}."));
}

/// Why event routines could not run.
pub(crate) enum HookFailure {
    /// The configuration names a routine the task does not have.
    Missing(String),
    /// An error no ERROR handler handled while the event routine (named) ran.
    Unhandled(String, rapid_vm::Unhandled),
}

/// Runs the event routines of system event `shelf` configured for `task`.
pub(crate) fn run_hooks(
    loaded: &mut rapid_vm::Loaded,
    host: &mut dyn rapid_vm::Host,
    sys: Option<&rapid_config::sys::Sys>,
    task: &str,
    shelf: &str,
) -> Result<(), HookFailure> {
    let Some(sys) = sys else { return Ok(()) };
    let event = rapid_config::sys::SHELVES.iter().position(|s| *s == shelf).map_or(0, |i| i as u8 + 1);
    for routine in sys.hooks_for(task, shelf) {
        match loaded.vm.run_event_routine(host, routine, event, loaded.entry) {
            Ok(true) => {}
            Ok(false) => {
                return Err(HookFailure::Missing(format!(
                    "task {task} has no procedure `{routine}` for its {shelf} event routine"
                )))
            }
            Err(unhandled) => return Err(HookFailure::Unhandled(routine.to_owned(), unhandled)),
        }
    }
    Ok(())
}

fn report_hook_failure(
    failure: HookFailure,
    loaded: &rapid_vm::Loaded,
    files: &[SourceInput],
) -> anyhow::Result<ExitStatus> {
    match failure {
        HookFailure::Missing(message) => {
            eprintln!("error: {message}");
            eprintln!("the system has errors; it was not run");
        }
        HookFailure::Unhandled(routine, unhandled) => {
            let source = files.get(unhandled.file).or(loaded.vm.program_source(unhandled.file));
            let (path, line, column) = match source {
                Some(input) => location(std::slice::from_ref(input), 0, unhandled.span.start),
                None => location(&[], 0, 0),
            };
            eprintln!("error: {}", unhandled.error);
            eprintln!("  in routine {} at {path}:{line}:{column}", unhandled.routine);
            eprintln!("  the event routine {routine} stopped (no ERROR handler handled the error)");
        }
    }
    Ok(ExitStatus::Failure)
}

/// The operator's answers of `--tp-input`, in order.
pub(crate) fn pendant_answers(args: &RunArgs) -> anyhow::Result<std::collections::VecDeque<String>> {
    let Some(path) = &args.tp_input else { return Ok(std::collections::VecDeque::new()) };
    let text = std::fs::read_to_string(path)
        .map_err(|e| anyhow::anyhow!("cannot read the pendant answers `{}`: {e}", path.display()))?;
    Ok(text.lines().filter(|l| !l.starts_with('#')).map(str::to_string).collect())
}

/// The controller root of the file devices (`--home`, else `rapid-controller` beside
/// the first PATH) and the loaded modules' files (ModExist, ModTimeDnum).
pub(crate) fn configure_files(
    loaded: &mut rapid_vm::Loaded,
    args: &RunArgs,
    files: &[SourceInput],
    backup_root: Option<std::path::PathBuf>,
) {
    let root = args.home.clone().or(backup_root).unwrap_or_else(|| default_home(&args.paths));
    let mut interner = rapid_syntax::Interner::default();
    let modules = files
        .iter()
        .filter(|f| f.unreadable.is_none())
        .flat_map(|f| {
            // Only the module names are needed: bodies are scanned over, not parsed.
            let parse = rapid_syntax::parse_outline(&f.text, &mut interner);
            let path = std::path::PathBuf::from(&f.path);
            let names: Vec<String> = parse.file.modules.iter().map(|m| m.name.span.text(&f.text).to_string()).collect();
            names.into_iter().map(move |name| ModuleFile { name, path: path.clone() })
        })
        .collect();
    let state = &mut loaded.vm.resources_mut().files;
    state.set_root(root);
    state.set_modules(modules);
}

/// `rapid-controller` in the folder holding the first PATH (for a folder of modules,
/// beside that folder).
fn default_home(paths: &[std::path::PathBuf]) -> std::path::PathBuf {
    let first = paths.first().map(|p| p.as_path()).unwrap_or(std::path::Path::new("."));
    let parent = match first.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    parent.join("rapid-controller")
}

pub(crate) fn location(files: &[SourceInput], file: usize, offset: u32) -> (String, u32, u32) {
    match files.get(file) {
        Some(input) => {
            let at = LineIndex::new(&input.text).line_col(&input.text, offset);
            (input.path.clone(), at.line, at.column)
        }
        None => ("<predefined>".into(), 0, 0),
    }
}

/// What the run says when Ctrl-C ended it at controller time `time`.
pub(crate) fn interrupted_at(time: f64) -> String {
    format!("interrupted (Ctrl-C) at {time:.3} s of controller time; the program did not end")
}

/// What the run says when ExitCycle ended `what` ("the cycle of T_A") in cycle mode:
/// a program restarting itself so (a server's main loop) would seem to stop for no
/// reason, so it says how to run on.
pub(crate) fn exit_cycle_note(what: &str) -> String {
    format!(
        "note: ExitCycle ended {what}; in cycle mode (the default) that ends the run: `--cycles 0` runs \
         continuously, each ExitCycle starting the next cycle"
    )
}

/// Prints the notes on how the inputs were read (a backup's module left out) to stderr.
pub(crate) fn print_notes(inputs: &inputs::Inputs) {
    for note in &inputs.notes {
        eprintln!("note: {note}");
    }
}

/// Whether the inputs' configuration has errors (the controller would not start), or a
/// `.pgf` entry does (the program is not whole): what `rapid check` refuses, run refuses.
pub(crate) fn has_config_errors(inputs: &inputs::Inputs) -> bool {
    let refused = |code| matches!(code, Code::ConfigFile | Code::ProgramFileEntry);
    inputs.diagnostics.iter().any(|d| refused(d.code) && d.severity() == Severity::Error)
}

/// Errors in a backup's configuration: the controller would not start, so nothing
/// runs (the report shows every input finding, warnings and `.pgf` entries too).
pub(crate) fn report_input_errors(inputs: &inputs::Inputs) -> anyhow::Result<ExitStatus> {
    report_system_errors(&inputs.table(), &inputs.diagnostics)
}

/// Findings that keep the system from starting, shown as `rapid check` shows them
/// (`files` is the table their `file` indexes).
pub(crate) fn report_system_errors(files: &[&SourceInput], diagnostics: &[Diagnostic]) -> anyhow::Result<ExitStatus> {
    let (files, reported) = (Files::new(files), Reported::untagged(diagnostics));
    let summary = Summary::of(&reported, &files);
    let mut out = io::stderr().lock();
    render::human::render(&mut out, &files, &reported, &summary)?;
    writeln!(out, "the system has errors; it was not run")?;
    Ok(ExitStatus::Failure)
}

pub(crate) fn report_load_error(err: LoadError, files: &[SourceInput]) -> anyhow::Result<ExitStatus> {
    match err {
        LoadError::Diagnostics(diagnostics) => {
            let table: Vec<&SourceInput> = files.iter().collect();
            let (files, reported) = (Files::new(&table), Reported::untagged(&diagnostics));
            let summary = Summary::of(&reported, &files);
            let mut out = io::stderr().lock();
            render::human::render(&mut out, &files, &reported, &summary)?;
            writeln!(out, "the program has errors; it was not run")?;
        }
        LoadError::Unsupported(errors) => {
            for e in errors {
                let (path, line, column) = location(files, e.file, e.span.start);
                eprintln!("error: {} ({path}:{line}:{column})", e.message);
            }
            eprintln!("the program was not run");
        }
        LoadError::NoEntry(name) => {
            eprintln!("error: no procedure `{name}` without parameters to start (use --entry NAME)");
            return Ok(ExitStatus::Error);
        }
        LoadError::Init(unhandled) => {
            eprintln!("error: while giving data its initial values: {}", unhandled.error);
        }
    }
    Ok(ExitStatus::Failure)
}

pub(crate) struct StdoutHost<'a> {
    pub(crate) out: BufWriter<io::StdoutLock<'a>>,
    pub(crate) broken: bool,
    pub(crate) answers: std::collections::VecDeque<String>,
}

impl StdoutHost<'_> {
    pub(crate) fn flush(&mut self) {
        if !self.broken && self.out.flush().is_err() {
            self.broken = true;
        }
    }
}

impl Host for StdoutHost<'_> {
    fn tp_write(&mut self, line: &str) {
        // A closed pipe (`rapid run x | head`) is not the program's fault: keep running.
        if !self.broken && writeln!(self.out, "{line}").is_err() {
            self.broken = true;
        }
        // The pendant shows a line when it is written: a program stopped by the user
        // (a server waiting on a socket, a continuous run) has its output out already.
        self.flush();
    }

    fn tp_answer(&mut self, _prompt: &str) -> Option<String> {
        self.answers.pop_front()
    }
}

/// The I/O system of the backup's EIO.cfg, and the stimulus for its inputs.
fn configure_io(
    loaded: &mut rapid_vm::Loaded,
    args: &RunArgs,
    syspar: &[(String, rapid_config::CfgFile)],
    modules: &[SourceInput],
) -> Result<(), String> {
    let eio = syspar.iter().find(|(domain, _)| domain.eq_ignore_ascii_case("EIO"));
    let mut system = match eio {
        Some((_, eio)) => Some(rapid_vm::builtins::io_config::io_system(&rapid_config::eio::read(eio))?),
        None => None,
    };
    if args.virtual_io {
        with_virtual_signals(&mut system, modules)?;
    }
    if let Some(system) = system {
        loaded.vm.install_io(system);
    }
    let Some(path) = &args.stimulus else { return Ok(()) };
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read the stimulus `{shown}`: {e}"))?;
    let io = &mut loaded.vm.resources_mut().io;
    let Some(system) = &io.system else {
        return Err(format!(
            "`{shown}`: a stimulus needs an I/O configuration (a backup with SYSPAR/EIO.cfg, or a manifest with `io`)"
        ));
    };
    let (orders, reactions, answers) = crate::stimulus::parse(&shown, &text, system)?;
    io.stimulus = orders.into();
    io.reactions = reactions;
    io.answers = answers.into();
    Ok(())
}

/// `--virtual-io`: the signals AliasIO names that the configuration lacks, as virtual
/// signals (an I/O system is made when there is none).
pub(crate) fn with_virtual_signals(
    system: &mut Option<rapid_io::IoSystem>,
    modules: &[SourceInput],
) -> Result<(), String> {
    let signals = crate::virtual_io::aliased_signals(modules);
    if system.is_none() {
        *system = Some(rapid_io::IoSystem::new(Vec::new(), Vec::new()).map_err(|e| e.to_string())?);
    }
    match system {
        Some(system) => crate::virtual_io::add_to(system, &signals),
        None => Ok(()),
    }
}

/// `x` with at most `places` decimals, trailing zeros dropped (times to the
/// millisecond, values to a millionth).
fn decimals(x: f64, places: usize) -> String {
    let text = format!("{x:.places$}");
    let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { &text };
    if text == "-0" {
        "0".to_string()
    } else {
        text.to_string()
    }
}

/// `--io-log`: every signal change as CSV (times in seconds to the millisecond, values
/// to a millionth), written atomically.
pub(crate) fn write_io_log(io: Option<&rapid_io::IoSystem>, path: &std::path::Path) -> anyhow::Result<()> {
    let mut csv = String::from("time,signal,old,new,cause\n");
    if let Some(system) = io {
        for change in system.changes() {
            csv.push_str(&format!(
                "{},{},{},{},{:?}\n",
                decimals(change.time, 3),
                change.signal,
                decimals(change.old, 6),
                decimals(change.new, 6),
                change.cause
            ));
        }
    }
    crate::save::write_new(path, csv.as_bytes())
}

/// The controller time the instructions run since `charged` took (`steps` now), which
/// are charged from here on.
fn computed(charged: &mut u64, steps: u64) -> f64 {
    let seconds = steps.saturating_sub(*charged) as f64 * rapid_controller::schedule::INSTRUCTION_TIME;
    *charged = steps;
    seconds
}

/// Whether the clock is past `--max-time` (then the run says so).
fn past_max_time(time: f64, args: &RunArgs, host: &mut StdoutHost<'_>) -> bool {
    match args.max_time {
        Some(max) if time > max => {
            host.flush();
            eprintln!("error: stopped at {max} s of controller time (--max-time); the program did not end");
            true
        }
        _ => false,
    }
}
