//! The execution log of SpyStart / SpyStop (§1.18 "执行的记录"): while it runs, every
//! executed instruction leaves one line in a file on a device: the task, the
//! instruction as written, the time it was entered, how it ended and the time it was
//! left (milliseconds since SpyStart, on the controller's clock).
//!
//! The executor (`exec/spy.rs`) runs instructions one at a time while the log is open
//! and calls [`SpyState::record`] once per executed statement; here are the file, its
//! layout and PP to Main ending the log.
//!
//! ```text
//! TASK    INSTR                                    IN    CODE    OUT
//! T_ROB1  reg1 := reg1 + 1;                        0     READY   0
//! T_ROB1  WaitTime 1;                              0     WAIT    1000
//! ```
// uncertain: ABB's manual shows such a table (TASK, INSTR, IN, CODE, OUT, times in ms,
// CODE READY for an instruction that ran through, WAIT for one that waited); the exact
// column widths are ours.

use std::io::{BufWriter, Write};

use super::Ctx;
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;
use crate::world::{HostFile, OpenMode};

type Res = Result<Option<Value>, RapidError>;

/// How an instruction ended (the CODE column).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpyCode {
    /// Executed without waiting.
    Ready,
    /// It waited (WaitTime, a socket, a dialog): OUT is later than IN.
    Wait,
    /// It raised an error.
    Error,
}

impl SpyCode {
    fn label(self) -> &'static str {
        match self {
            SpyCode::Ready => "READY",
            SpyCode::Wait => "WAIT",
            SpyCode::Error => "ERROR",
        }
    }
}

/// The open execution log, if SpyStart started one.
#[derive(Default)]
pub struct SpyState {
    log: Option<SpyLog>,
}

struct SpyLog {
    out: BufWriter<Box<dyn HostFile>>,
    /// Controller time (seconds) at SpyStart: the log's zero.
    started_at: f64,
}

/// Milliseconds since the log's zero, as a whole number.
fn millis(started_at: f64, time: f64) -> u64 {
    ((time - started_at).max(0.0) * 1000.0).round() as u64
}

impl SpyState {
    /// Whether instructions are being logged (the executor asks before it formats).
    pub fn is_active(&self) -> bool {
        self.log.is_some()
    }

    /// Logs one executed instruction: `instr` is its source text, `time_in` and
    /// `time_out` controller times in seconds, `task` the task that ran it. A write failure ends the log (the
    /// program must not stop because its debugging log could not be written).
    pub fn record(&mut self, task: &str, instr: &str, time_in: f64, code: SpyCode, time_out: f64) {
        let Some(log) = self.log.as_mut() else { return };
        let line = format_line(task, instr, millis(log.started_at, time_in), code, millis(log.started_at, time_out));
        if writeln!(log.out, "{line}").is_err() {
            self.log = None;
        }
    }

    /// Ends the log and writes out what is buffered (SpyStop, PP to Main).
    pub fn stop(&mut self) {
        if let Some(mut log) = self.log.take() {
            // Nothing to report to: the program asked for the stop or has ended.
            let _ = log.out.flush();
        }
    }
}

/// One line of the log; the instruction is on one line, blanks collapsed.
fn format_line(task: &str, instr: &str, time_in: u64, code: SpyCode, time_out: u64) -> String {
    let instr = instr.split_whitespace().collect::<Vec<_>>().join(" ");
    format!("{task:<8}{instr:<40} {time_in:<5} {:<7} {time_out}", code.label())
}

const HEADER: &str = "TASK    INSTR                                    IN    CODE    OUT";

/// `SpyStart File`: starts the log in File (emptied first). ERR_FILEOPEN if the file
/// cannot be made (manual). A log already running is ended first.
// uncertain: the manual does not say what a second SpyStart does; we end the first log.
pub fn spy_start(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let path = ctx.string(&args[0])?;
    let resolved = ctx.resolve_path(&path).map_err(|fault| ctx.error(Err::FileOpen, fault.message()))?;
    let create = OpenMode { write: true, create: true, truncate: true, ..OpenMode::default() };
    let file = ctx
        .resources
        .devices
        .file_system()
        .open(&resolved.path, create)
        .map_err(|e| ctx.error(Err::FileOpen, format!("the spy file `{path}` cannot be made: {e}")))?;
    let mut out = BufWriter::new(file);
    writeln!(out, "{HEADER}").map_err(|e| ctx.error(Err::FileOpen, format!("the spy file `{path}`: {e}")))?;
    let spy = &mut ctx.resources.spy;
    spy.stop();
    spy.log = Some(SpyLog { out, started_at: ctx.time });
    Ok(None)
}

/// `SpyStop`: ends the log; without one it does nothing.
pub fn spy_stop(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    ctx.resources.spy.stop();
    Ok(None)
}

pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[super::native("SpyStart", spy_start), super::native("SpyStop", spy_stop)],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_have_the_columns_of_the_header() {
        let line = format_line("T_ROB1", "WaitTime  1;", 0, SpyCode::Wait, 1000);
        assert_eq!(line.find("WaitTime"), HEADER.find("INSTR"));
        assert_eq!(line.find("WAIT "), HEADER.find("CODE"));
        assert!(line.ends_with(" 1000"));
        assert_eq!(millis(2.0, 2.0015), 2);
        assert_eq!(millis(2.0, 1.0), 0);
    }

    #[test]
    fn records_until_stopped() {
        let dir = std::env::temp_dir().join(format!("rapid-spy-unit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let path = dir.join("spy.log");
        let mut spy = SpyState::default();
        spy.record("T_ROB1", "ignored;", 0.0, SpyCode::Ready, 0.0);
        let file = std::fs::File::create(&path).expect("file");
        spy.log = Some(SpyLog { out: BufWriter::new(Box::new(file)), started_at: 1.0 });
        assert!(spy.is_active());
        spy.record("T_ROB1", "a := 1;", 1.0, SpyCode::Ready, 1.0);
        spy.record("T_ROB1", "WaitTime 0.5;", 1.0, SpyCode::Wait, 1.5);
        spy.stop();
        spy.record("T_ROB1", "after;", 2.0, SpyCode::Ready, 2.0);
        let text = std::fs::read_to_string(&path).expect("log");
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2);
        assert!(lines[0].starts_with("T_ROB1  a := 1;"));
        assert!(lines[1].contains("WAIT") && lines[1].ends_with(" 500"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
