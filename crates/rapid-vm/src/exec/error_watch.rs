//! A debugger's exception breakpoints: the VM notes an error an ERROR handler is
//! about to take ("raised", the task standing at the handler's first statement), and
//! holds back the end of a task whose error no handler takes ("uncaught", the task
//! standing where it was raised, its call stack whole) until it runs on. The
//! controller takes the note before the task's next statement and stops the program.
//! Nothing here is looked at unless a front end asked for it.

use super::{Exit, Vm};
use crate::error::RapidError;

/// What a front end asked to stop at, and a stop not yet taken.
#[derive(Debug, Default)]
pub(super) struct ErrorWatch {
    raised: bool,
    uncaught: bool,
    stop: Option<ErrorStop>,
    /// The end of the task, held while it stands stopped at its uncaught error.
    pending: Option<Exit>,
}

/// An error a debugger stops at.
#[derive(Debug, Clone, PartialEq)]
pub struct ErrorStop {
    pub error: RapidError,
    /// No ERROR handler takes it: when the task runs on, it stops with the error.
    pub uncaught: bool,
}

impl Vm {
    /// Stops at errors: `raised`, each error an ERROR handler takes, before the handler
    /// runs; `uncaught`, an error no handler takes, before the task stops with it.
    pub fn watch_errors(&mut self, raised: bool, uncaught: bool) {
        self.error_watch.raised = raised;
        self.error_watch.uncaught = uncaught;
        self.error_watch.stop = None;
    }

    /// The error the task stands stopped at, once.
    pub fn take_error_stop(&mut self) -> Option<ErrorStop> {
        self.error_watch.stop.take()
    }

    /// A stop waits to be taken: the statement under way ends here.
    pub(super) fn error_stop_waits(&self) -> bool {
        self.error_watch.stop.is_some()
    }

    /// An ERROR handler is about to take `error`.
    pub(super) fn note_raised(&mut self, error: &RapidError) {
        if self.error_watch.raised {
            self.error_watch.stop = Some(ErrorStop { error: error.clone(), uncaught: false });
        }
    }

    /// The end of a task whose error no handler took (`exit`). Watched (outside an
    /// UNDO run), the call stack is kept and the task stands where it is: `Budget`
    /// now, the end when it runs on ([`Vm::take_pending_end`]).
    pub(super) fn give_up(&mut self, exit: Exit) -> Exit {
        if self.error_watch.uncaught && !self.exiting {
            if let Exit::Unhandled(unhandled) = &exit {
                self.error_watch.stop = Some(ErrorStop { error: unhandled.error.clone(), uncaught: true });
                // The task stands at the start of the failing statement, a boundary a
                // stop may settle at; it never runs that statement again.
                if let Some(top) = self.frames.last_mut() {
                    if let Some(stmt) = top.code.stmt_at(top.pc) {
                        top.pc = stmt.start;
                    }
                }
                self.error_watch.pending = Some(exit);
                return Exit::Budget;
            }
        }
        self.frames.clear();
        exit
    }

    /// The held end of the task, when it runs on from its uncaught error.
    pub(super) fn take_pending_end(&mut self) -> Option<Exit> {
        let exit = self.error_watch.pending.take()?;
        self.frames.clear();
        Some(exit)
    }

    /// A new start forgets an error the task stood at.
    pub(super) fn forget_error_stop(&mut self) {
        self.error_watch.stop = None;
        self.error_watch.pending = None;
    }
}
