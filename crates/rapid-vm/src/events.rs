//! The controller's event log as RAPID writes to it: ErrWrite, ErrLog, ErrRaise and
//! errors that reach the system error handler. Clients read it through
//! [`crate::exec::Vm::event_log`]; `rapid run --event-log` prints it.

use std::fmt;

use rapid_syntax::Span;

/// The user domain (USER_DEF_ERR): what ErrWrite, ErrLog and ErrRaise write.
pub const USER_DOMAIN: u32 = 8;
/// The program domain (PROGRAM_ERR): errors stopped by the system error handler.
pub const PROGRAM_DOMAIN: u32 = 4;
/// The operational domain (OP_STATE): state changes of the controller and its tasks.
pub const OPERATIONAL_DOMAIN: u32 = 1;
/// The motion domain (MOTION): what the motion system reports (corner path failures).
pub const MOTION_DOMAIN: u32 = 5;

/// Operational state changes `rapid run` logs, as (number, title): the event code is
/// the domain × 10000 + the number (10002, 10150, 10151).
// uncertain: numbers and titles as we remember RobotWare 6's event log.
pub const PP_RESET: (u32, &str) = (2, "Program pointer has been reset");
pub const PROGRAM_STARTED: (u32, &str) = (150, "Program started");
pub const PROGRAM_STOPPED: (u32, &str) = (151, "Program stopped");

/// Program-domain warnings of the UNDO context (manual §1.13), as (number, title): an
/// instruction ignored there (STOP, BREAK, RAISE, RETURN: code 40901), and an UNDO
/// session cut short by EXIT or a run error (40902). ABB's own numbers and texts for
/// these warnings are not public: ours, outside the errnum values (1..90 and 1000..)
/// that the program domain's error entries use as numbers (`exec/undo.rs`).
pub const IGNORED_IN_UNDO: (u32, &str) = (901, "Instruction ignored in UNDO");
pub const UNDO_ABORTED: (u32, &str) = (902, "UNDO aborted");

/// How serious an event is (the `\W` and `\I` switches of ErrWrite and ErrLog).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    Error,
    Warning,
    Info,
}

/// The log keeps the newest entries up to this many, like the controller's bounded
/// event log (its real size per domain is not in the public record: uncertain).
pub const LOG_CAPACITY: usize = rapid_limits::EVENT_LOG_ENTRIES;

/// The event log: entries oldest first, each with a sequence number.
#[derive(Debug, Default)]
pub struct EventLog {
    entries: Vec<Event>,
    next_seq: u64,
}

impl EventLog {
    /// Appends `event`, numbering it; returns its sequence number. Past
    /// [`LOG_CAPACITY`] the oldest entries are dropped.
    pub fn push(&mut self, mut event: Event) -> u64 {
        let seq = self.next_seq;
        self.next_seq += 1;
        event.seq = seq;
        if self.entries.len() >= LOG_CAPACITY {
            // Drop a tenth at once so that a flood of events costs O(1) per push.
            self.entries.drain(..LOG_CAPACITY / 10);
        }
        self.entries.push(event);
        seq
    }

    /// Removes the entry numbered `seq`, if it is still in the log (SkipWarn).
    pub fn remove(&mut self, seq: u64) {
        if let Some(index) = self.entries.iter().rposition(|e| e.seq == seq) {
            self.entries.remove(index);
        }
    }

    pub fn entries(&self) -> &[Event] {
        &self.entries
    }

    /// The number the next entry will get.
    pub fn next_seq(&self) -> u64 {
        self.next_seq
    }

    /// Gives the entries numbered `from` on that have no place yet the place `at`
    /// (the VM knows where a built-in that logged was called; the built-in does not).
    pub fn place_since(&mut self, from: u64, at: &EventPlace) {
        for event in self.entries.iter_mut().rev().take_while(|e| e.seq >= from) {
            if event.place.is_none() {
                event.place = Some(at.clone());
            }
        }
    }
}

/// Where an event was logged: the routine and the statement running.
#[derive(Debug, Clone, PartialEq)]
pub struct EventPlace {
    pub routine: String,
    /// The program file (an index of the VM's sources: the task's files, then
    /// modules loaded at run time; `usize::MAX` for none).
    pub file: usize,
    /// The statement, in that file.
    pub span: Span,
}

/// One event-log entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Event {
    /// Its place in the log since the program was loaded (set by [`EventLog::push`]).
    pub seq: u64,
    pub domain: u32,
    /// The number inside the domain (ErrLog's ErrorId, 1..3 for ErrWrite).
    pub number: u32,
    pub kind: EventKind,
    /// Controller time (virtual seconds) when it was logged.
    pub time: f64,
    pub title: String,
    /// The message lines after the title, unused arguments left out.
    pub lines: Vec<String>,
    /// Where it was logged, when it came from running code.
    pub place: Option<EventPlace>,
}

impl Event {
    /// The code the pendant shows: domain × 10000 + number (80001 for an ErrWrite).
    /// The ×10000 layout is how the public manuals write the ErrWrite codes (80001,
    /// 80002, 80003); that ErrLog's 4800 shows as 84800 follows from it (uncertain).
    pub fn code(&self) -> u32 {
        self.domain * 10_000 + self.number
    }
}

impl fmt::Display for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self.kind {
            EventKind::Error => "error",
            EventKind::Warning => "warning",
            EventKind::Info => "information",
        };
        write!(f, "{} {kind}: {}", self.code(), self.title)?;
        for line in &self.lines {
            write!(f, "\n    {line}")?;
        }
        Ok(())
    }
}

/// The four predefined `errstr` markers (declared in the catalogue's data.rs). The
/// controller fills in the task name and the error context for the first two,
/// shows an empty line for ERRSTR_EMPTY and leaves ERRSTR_UNUSED out.
pub const ERRSTR_TASK: &str = "<ERRSTR_TASK>";
pub const ERRSTR_CONTEXT: &str = "<ERRSTR_CONTEXT>";
pub const ERRSTR_EMPTY: &str = "<ERRSTR_EMPTY>";
pub const ERRSTR_UNUSED: &str = "<ERRSTR_UNUSED>";

/// An errstr argument as the log shows it; `None` for ERRSTR_UNUSED.
pub fn expand_errstr(text: &str, task: &str, context: &str) -> Option<String> {
    match text {
        ERRSTR_UNUSED => None,
        ERRSTR_EMPTY => Some(String::new()),
        ERRSTR_TASK => Some(task.to_string()),
        ERRSTR_CONTEXT => Some(context.to_string()),
        other => Some(other.to_string()),
    }
}
