//! The UNDO context's restrictions (manual §1.13): STOP, BREAK, RAISE and RETURN are
//! ignored there with an event-log warning, and EXIT aborts the UNDO session.
//!
//! §1.13 defines the UNDO context as "the current routine is part of a call chain
//! starting in an UNDO handler": the handler and every routine it calls while it runs.
//! Which of the four instructions is looked at where:
//! - Stop and Break (built-ins, `builtins/system.rs`) and `RAISE n` (`Instr::Raise`) are
//!   ignored anywhere in that chain: each would end or leave the UNDO session.
//! - RETURN is ignored only when written in the UNDO handler itself: the compiler
//!   turns it into `Instr::UndoReturn` (`compile/stmt.rs`). A RETURN in a routine the
//!   handler calls ends that routine as usual, and a FUNC's RETURN gives its value.
//!   Why: §1.13 says "UNDO-处理器不得含有…RETURN" (the handler must not contain it) and
//!   then ignores the four "在UNDO上下文中"; taken literally for RETURN, no FUNC could
//!   return a value in UNDO context, and a routine shared by normal code and UNDO
//!   (`IF NOT open RETURN; Close f;`) would run on past its RETURN there. A RETURN in a
//!   called routine only goes back to its caller inside the same UNDO context, so it
//!   cannot cut the UNDO short, which is what the rule prevents ("在UNDO中,执行是一个
//!   连续过程,不可能跳过"). The public record does not say more (uncertain).
//! - Bare RAISE, RETRY and TRYNEXT are allowed only in ERROR handlers (the checker's
//!   E0608/E0601 refuse them in UNDO), and no ERROR handler runs during UNDO (errors
//!   there stop the program), so none of them can run in UNDO context.
//! - EXIT "aborts UNDO like a run error or a stop: the rest of the UNDO handlers are
//!   ignored" (§1.13): the program ends at once, and, as for every UNDO cut short, an
//!   event-log warning says so ("若执行UNDO-处理器期间终止程序…而这会导致出现ELOG警告").

use super::{Exit, Frame, Vm};
use crate::events::{Event, EventKind, EventLog, EventPlace, IGNORED_IN_UNDO, PROGRAM_DOMAIN, UNDO_ABORTED};

/// Whether a task whose call chain is `chain` runs in UNDO context: some routine of
/// the chain runs its UNDO handler (every routine above it was called from there).
pub(crate) fn in_undo_context(chain: &[Frame]) -> bool {
    chain.iter().any(|frame| frame.undoing)
}

/// Logs the warning for `instruction` (`STOP`, `BREAK`, `RAISE`, `RETURN`) ignored in
/// UNDO context by `routine`; `place` is `None` when the caller places it afterwards
/// (a built-in does not know where it was called from).
pub(crate) fn log_ignored(
    events: &mut EventLog,
    time: f64,
    instruction: &str,
    routine: &str,
    place: Option<EventPlace>,
) {
    events.push(Event {
        seq: 0,
        domain: PROGRAM_DOMAIN,
        number: IGNORED_IN_UNDO.0,
        kind: EventKind::Warning,
        time,
        title: IGNORED_IN_UNDO.1.to_string(),
        details: Vec::new(),
        lines: vec![
            format!("{instruction} is not allowed in UNDO context: it was not executed."),
            format!("routine {routine}"),
        ],
        place,
    });
}

impl Vm {
    /// `RAISE n` in UNDO context: ignored with a warning (the number was evaluated
    /// and popped already). `false` outside UNDO context: raise as usual.
    pub(super) fn raise_ignored_in_undo(&mut self) -> bool {
        if !in_undo_context(&self.frames) {
            return false;
        }
        self.log_ignored_here("RAISE");
        true
    }

    /// `Instr::UndoReturn`: a RETURN written in an UNDO handler, ignored.
    pub(super) fn undo_return(&mut self) {
        self.log_ignored_here("RETURN");
    }

    fn log_ignored_here(&mut self, instruction: &str) {
        let Some(frame) = self.frames.last() else { return };
        let place = Self::place_of(frame);
        let routine = place.routine.clone();
        log_ignored(&mut self.events, self.time, instruction, &routine, Some(place));
    }

    /// EXIT: in UNDO context it aborts the UNDO session (the handlers not yet run are
    /// skipped, with a warning); elsewhere it starts the UNDO handlers of the chain.
    pub(super) fn exit_instruction(&mut self) -> Option<Exit> {
        if !in_undo_context(&self.frames) {
            return self.exit();
        }
        self.log_undo_aborted("EXIT", None);
        self.frames.clear();
        self.storage.stack.clear();
        // EXIT ends the program even in the UNDO of an ExitCycle: no next cycle.
        self.cycle_exit = false;
        Some(Exit::Done)
    }

    /// The warning for an UNDO session cut short by `cause` (EXIT, or the name of a
    /// run error no handler takes) at `place` (the top frame's statement when `None`),
    /// naming how many UNDO handlers of the chain are skipped.
    pub(super) fn log_undo_aborted(&mut self, cause: &str, place: Option<EventPlace>) {
        let Some(place) = place.or_else(|| self.frames.last().map(Self::place_of)) else { return };
        // The routine running its handler is skipped no further; those below it are.
        let running = self.frames.iter().rposition(|f| f.undoing).unwrap_or(0);
        let skipped = self.frames[..running].iter().filter(|f| f.code.undo_handler.is_some()).count();
        self.events.push(Event {
            seq: 0,
            domain: PROGRAM_DOMAIN,
            number: UNDO_ABORTED.0,
            kind: EventKind::Warning,
            time: self.time,
            title: UNDO_ABORTED.1.to_string(),
            details: Vec::new(),
            lines: vec![
                match skipped {
                    0 => format!("{cause} in UNDO context: the rest of the running UNDO handler was skipped."),
                    n => format!(
                        "{cause} in UNDO context: the rest of the running UNDO handler and {n} more UNDO handler(s) of the call chain were skipped."
                    ),
                },
                format!("routine {}", place.routine),
            ],
            place: Some(place),
        });
    }
}
