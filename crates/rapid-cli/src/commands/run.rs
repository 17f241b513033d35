//! `rapid run PATH…`: has the controller assemble the system of PATH
//! (`rapid_controller::assembly`, the path every front end takes), says why when it
//! cannot start, and hands it to the one run path (`run_system.rs`: the controller runs
//! every program, a single task as a system of one); what both need lives here: pendant output goes to stdout, one line
//! per write, an unhandled error is reported on stderr as the system error handler's
//! event-log entry would be, and the logs written after the run.

// The CLI is the one crate that talks to the terminal; run reports on stderr.
#![allow(clippy::print_stderr)]

use std::io::{self, BufWriter, Write};

use rapid_sema::{Diagnostic, SourceInput};
use rapid_syntax::LineIndex;
use rapid_vm::{Host, LoadError, Prompt};

use rapid_controller::assembly::inputs::Inputs;
use rapid_controller::assembly::{self, AssemblyError, LoadOptions};
use rapid_controller::boot::system::BootError;

use crate::args::RunArgs;
use crate::commands::ExitStatus;
use crate::render::{self, Files, Reported, Summary};

/// What `rapid run` says when the program executed WarmStart (the run ends there).
pub(crate) const WARM_START: &str =
    "warm start: the program requested a restart of the controller (WarmStart); the run ends here";

pub(crate) fn run(args: &RunArgs) -> anyhow::Result<ExitStatus> {
    // Every program runs under the controller: one task alone, or a system of tasks,
    // assembled by the one path every front end takes.
    let assembly = assembly::assemble(&args.paths, &load_options(args));
    print_notes(&assembly.notes);
    let assembled = match assembly.outcome {
        Ok(assembled) => assembled,
        Err(err) => return report_assembly_error(err),
    };
    super::run_system::run(args, assembled)
}

/// The command line's run options as the controller's assembly takes them.
fn load_options(args: &RunArgs) -> LoadOptions {
    LoadOptions {
        operated: false,
        entry: args.entry.clone(),
        virtual_io: args.virtual_io,
        state: args.controller_state(),
        home: args.home.clone(),
        robot: args.robot.clone(),
        record: args.trace.is_some() || args.report.is_some(),
        cycles: args.cycles,
        max_steps: args.max_steps,
        start_joints: args.start_joints,
        stimulus: args.stimulus.clone(),
        controller_ip: args.controller_ip,
    }
}

/// Why the system was not run, said as `rapid check` says findings (input and system
/// findings), as the program's load error, or as a refusal.
fn report_assembly_error(err: AssemblyError) -> anyhow::Result<ExitStatus> {
    match err {
        AssemblyError::Unreadable(err) => Err(err.into()),
        AssemblyError::Inputs(inputs) => report_input_errors(&inputs),
        AssemblyError::System { files, diagnostics } => {
            let table: Vec<&SourceInput> = files.iter().collect();
            report_system_errors(&table, &diagnostics)
        }
        AssemblyError::Load { task, alone, error, files } => {
            if !alone {
                eprintln!("error: task {task} cannot start:");
            }
            report_load_error(*error, &files)
        }
        AssemblyError::Boot(BootError::Refused(message)) => refuse(&message),
        AssemblyError::Boot(BootError::UnknownModel(message)) => {
            eprintln!("error: {message}");
            Ok(ExitStatus::Error)
        }
        AssemblyError::Boot(BootError::Internal(message)) => Err(anyhow::anyhow!("internal error: {message}")),
    }
}

/// A system that cannot start: the message, and that nothing ran.
pub(crate) fn refuse(message: &str) -> anyhow::Result<ExitStatus> {
    eprintln!("error: {message}");
    eprintln!("the system has errors; it was not run");
    Ok(ExitStatus::Failure)
}

/// The event log's entry for the program's stop, with why it stopped.
pub(crate) fn log_stop(vm: &mut rapid_vm::Vm, task: &str, status: ExitStatus) {
    let why = match status {
        ExitStatus::Success => "the program ended",
        _ => "an error or a bound of the run stopped it",
    };
    vm.log_state(rapid_vm::events::PROGRAM_STOPPED, format!("Program execution in task {task} has stopped: {why}."));
}

/// The operator's answers of `--tp-input`, in order.
pub(crate) fn pendant_answers(args: &RunArgs) -> anyhow::Result<std::collections::VecDeque<String>> {
    let Some(path) = &args.tp_input else { return Ok(std::collections::VecDeque::new()) };
    let text = std::fs::read_to_string(path)
        .map_err(|e| anyhow::anyhow!("cannot read the pendant answers `{}`: {e}", path.display()))?;
    Ok(text.lines().filter(|l| !l.starts_with('#')).map(str::to_string).collect())
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
pub(crate) fn print_notes(notes: &[String]) {
    for note in notes {
        eprintln!("note: {note}");
    }
}

/// Errors in a backup's configuration: the controller would not start, so nothing
/// runs (the report shows every input finding, warnings and `.pgf` entries too).
fn report_input_errors(inputs: &Inputs) -> anyhow::Result<ExitStatus> {
    report_system_errors(&inputs.table(), &inputs.diagnostics)
}

/// Findings that keep the system from starting, shown as `rapid check` shows them
/// (`files` is the table their `file` indexes).
fn report_system_errors(files: &[&SourceInput], diagnostics: &[Diagnostic]) -> anyhow::Result<ExitStatus> {
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

    fn note(&mut self, text: &str) {
        eprintln!("note: {text}");
    }

    // A `\Visualize` box takes no answer: the run shows it on stderr (stdout is the
    // pendant's TP output, which the box is not part of) when it opens and closes.
    fn visualize_open(&mut self, prompt: &Prompt<'_>) {
        eprintln!("pendant: {} shows a message box while it waits: {}", prompt.task, prompt.text.replace('\n', " / "));
    }

    fn visualize_close(&mut self, prompt: &Prompt<'_>) {
        eprintln!("pendant: {} closes the message box: {}", prompt.task, prompt.text.replace('\n', " / "));
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
