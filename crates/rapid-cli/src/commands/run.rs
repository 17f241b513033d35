//! `rapid run PATH…`: reads the inputs like `rapid check` and hands them to the one
//! run path (`run_system.rs`: the controller runs every program, a single task as a
//! system of one); what both need lives here: pendant output goes to stdout, one line
//! per write, an unhandled error is reported on stderr as the system error handler's
//! event-log entry would be, and the logs written after the run.

// The CLI is the one crate that talks to the terminal; run reports on stderr.
#![allow(clippy::print_stderr)]

use std::io::{self, BufWriter, Write};

use rapid_sema::{Code, Diagnostic, Severity, SourceInput};
use rapid_syntax::LineIndex;
use rapid_vm::{Host, LoadError, Prompt};

use crate::args::RunArgs;
use crate::commands::ExitStatus;
use crate::render::{self, Files, Reported, Summary};
use rapid_controller::assembly::inputs;

/// What `rapid run` says when the program executed WarmStart (the run ends there).
pub(crate) const WARM_START: &str =
    "warm start: the program requested a restart of the controller (WarmStart); the run ends here";

pub(crate) fn run(args: &RunArgs) -> anyhow::Result<ExitStatus> {
    let inputs = inputs::collect(&args.paths)?;
    print_notes(&inputs);
    if has_config_errors(&inputs) {
        return report_input_errors(&inputs);
    }
    // Every program runs under the controller: one task alone, or a system of tasks.
    super::run_system::run(args, inputs)
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

/// The controller root of the file devices: `--home`, else a backup's (or a
/// manifest's) own root, else `rapid-controller` beside the first PATH.
pub(crate) fn home(args: &RunArgs, backup_root: Option<std::path::PathBuf>) -> std::path::PathBuf {
    args.home.clone().or(backup_root).unwrap_or_else(|| default_home(&args.paths))
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
