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
    /// The detail of an error the system logs, in short strings before `lines`: what
    /// ReadErrData's `\Str1`… return first (empty for the program's own messages,
    /// whose lines are their arguments).
    pub details: Vec<String>,
    /// Where it was logged, when it came from running code.
    pub place: Option<EventPlace>,
}

impl Event {
    /// An entry the program logs itself (ErrWrite, ErrLog) in the user domain at
    /// controller time `time`: `title`, then the message `lines`. The VM adds where the
    /// program logged it (it knows the calling statement) and the log its `seq`.
    pub fn user(number: u32, kind: EventKind, time: f64, title: String, lines: Vec<String>) -> Event {
        Event { seq: 0, domain: USER_DOMAIN, number, kind, time, title, lines, details: Vec::new(), place: None }
    }

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
        for line in self.details.iter().chain(&self.lines) {
            write!(f, "\n    {line}")?;
        }
        Ok(())
    }
}

/// The longest title an event gets: what ErrWrite's header may hold (46 characters,
/// RAPID instructions manual), so a title framed in a program's own text still fits
/// a string (80 characters).
pub const TITLE_MAX_CHARS: usize = 46;
/// The longest detail string of a system error: detail is split at word ends into
/// strings of at most this many characters.
// uncertain: the controller's message arguments are short (names, numbers); 40 keeps
// each one short enough to be framed in a line of a program's own report.
pub const DETAIL_MAX_CHARS: usize = 40;
/// At most this many detail strings (ReadErrData has five, `\Str1`…`\Str5`, and the
/// place of the error comes after them).
pub const DETAIL_MAX_STRINGS: usize = 4;

/// The title and detail strings of an error's entry, split as the controller splits
/// its messages: a short title (the error's name, the motion system's text without
/// its number) and the rest of the message in short strings.
// uncertain: the controller titles its program errors with texts of its own ("Division
// by zero"), whose list is not public; the error's name is as short and names it.
pub fn split_error_text(name: &str, errno: i32, message: &str, motion: bool) -> (String, Vec<String>) {
    let (title, detail) = if motion {
        // "50050 Position outside reach" or "50080 Position not compatible (why)".
        let text = message.trim_start_matches(|c: char| c.is_ascii_digit()).trim_start();
        match text.split_once(" (") {
            Some((title, rest)) => (title.to_string(), rest.trim_end_matches(')').to_string()),
            None => (text.to_string(), String::new()),
        }
    } else if !name.is_empty() {
        (name.to_string(), message.to_string())
    } else if errno != 0 {
        (format!("Error {errno}"), message.to_string())
    } else {
        // uncertain: the controller's title for a stop of its own limits; "Execution
        // error" is the generic title of its program-domain entries as we remember them.
        ("Execution error".to_string(), message.to_string())
    };
    (title.chars().take(TITLE_MAX_CHARS).collect(), wrap_words(&detail, DETAIL_MAX_CHARS, DETAIL_MAX_STRINGS))
}

/// `text` cut at word ends into at most `max_strings` strings of at most `width`
/// characters (a word longer than `width` is cut); what does not fit is left out.
fn wrap_words(text: &str, width: usize, max_strings: usize) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut current = String::new();
    for word in text.split_whitespace() {
        let mut word: String = word.to_string();
        loop {
            let used = current.chars().count();
            let need = word.chars().count() + usize::from(used > 0);
            if used + need <= width {
                if used > 0 {
                    current.push(' ');
                }
                current.push_str(&word);
                break;
            }
            if used > 0 {
                out.push(std::mem::take(&mut current));
                continue;
            }
            // A word longer than a whole string: cut it.
            let head: String = word.chars().take(width).collect();
            word = word.chars().skip(width).collect();
            out.push(head);
            if word.is_empty() {
                break;
            }
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    out.truncate(max_strings);
    out
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_named_error_has_its_name_as_title_and_the_message_in_short_strings() {
        let message = "the argument of the instruction is outside the range the manual allows for it";
        let (title, detail) = split_error_text("ERR_ARGVALERR", 1050, message, false);
        assert_eq!(title, "ERR_ARGVALERR");
        assert_eq!(detail, ["the argument of the instruction is", "outside the range the manual allows for", "it"]);
        assert!(detail.iter().all(|d| d.chars().count() <= DETAIL_MAX_CHARS));
    }

    #[test]
    fn a_motion_error_loses_its_number_and_moves_its_reason_to_the_detail() {
        let (title, detail) =
            split_error_text("", 0, "50080 Position not compatible (the programmed configuration)", true);
        assert_eq!(title, "Position not compatible");
        assert_eq!(detail, ["the programmed configuration"]);
        let (title, detail) = split_error_text("", 0, "50050 Position outside reach", true);
        assert_eq!((title.as_str(), detail.len()), ("Position outside reach", 0));
    }

    #[test]
    fn long_words_are_cut_and_at_most_four_strings_are_kept() {
        let word = "x".repeat(100);
        let (title, detail) = split_error_text("", 0, &word, false);
        assert_eq!(title, "Execution error");
        assert_eq!(detail.iter().map(|d| d.chars().count()).collect::<Vec<_>>(), [40, 40, 20]);
        let many = "word ".repeat(60);
        let (_, detail) = split_error_text("", 7, &many, false);
        assert_eq!(detail.len(), DETAIL_MAX_STRINGS);
        let (title, _) = split_error_text("", 7, "", false);
        assert_eq!(title, "Error 7");
    }
}
