//! Backward execution (§1.21): a debugger steps the program pointer back one
//! instruction at a time. A call of a procedure runs backward by running its BACKWARD
//! handler (an empty one does nothing); a procedure without one cannot be stepped
//! back through; backward execution does not leave IF, FOR, WHILE or TEST, nor go past
//! the start of a routine. Instructions without a backward meaning are stepped over
//! (motion, which has one, comes with issue 6).

use super::{Exit, Vm};
use crate::host::Host;

/// What one step backward did.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BackStep {
    /// The program pointer moved back over an instruction.
    Moved,
    /// A procedure call ran backward: its BACKWARD handler ran.
    RanBackwardHandler(String),
}

/// Why a step backward is refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BackwardRefusal {
    NotRunning,
    /// Error, UNDO and BACKWARD handlers are not executed backward.
    InHandler,
    /// The program pointer is inside an IF, FOR, WHILE or TEST.
    InsideCompoundStatement,
    AtRoutineStart,
    /// The previous instruction calls a procedure without a BACKWARD handler.
    NoBackwardHandler(String),
    /// The BACKWARD handler failed or did not finish.
    HandlerFailed(String),
}

impl Vm {
    /// Steps the program pointer of the innermost routine back one instruction.
    pub fn step_backward(&mut self, host: &mut dyn Host) -> Result<BackStep, BackwardRefusal> {
        let Some(frame) = self.frames.last() else { return Err(BackwardRefusal::NotRunning) };
        if frame.active.is_some() || frame.undoing || frame.return_to.is_some() {
            return Err(BackwardRefusal::InHandler);
        }
        let (code, pc, depth) = (frame.code.clone(), frame.pc, self.frames.len());
        let mut top_level = code.stmts.iter().filter(|s| s.depth == 0);
        if top_level.clone().any(|s| s.start < pc && pc < s.end) {
            return Err(BackwardRefusal::InsideCompoundStatement);
        }
        // The handlers follow the body, each starting where the part before it ends.
        let handlers = [code.error_handler.as_ref().map(|h| h.pc), code.undo_handler, code.backward_handler];
        let body_end = handlers.into_iter().flatten().min();
        if body_end.is_some_and(|end| pc >= end) {
            return Err(BackwardRefusal::InHandler);
        }
        let Some(prev) = top_level.rfind(|s| s.end <= pc) else {
            return Err(BackwardRefusal::AtRoutineStart);
        };
        let Some(callee_idx) = prev.calls else {
            self.frame_mut().pc = prev.start;
            return Ok(BackStep::Moved);
        };
        let callee = self.routines.get(callee_idx as usize).cloned().flatten();
        let Some(callee) = callee.filter(|c| c.backward_handler.is_some()) else {
            let name =
                self.routines.get(callee_idx as usize).cloned().flatten().map_or(String::new(), |c| c.name.clone());
            return Err(BackwardRefusal::NoBackwardHandler(name));
        };
        // Re-evaluate the call's arguments and enter the callee at its BACKWARD
        // handler; when it returns, the PP stands on the call.
        self.frame_mut().pc = prev.start;
        self.backward_entry = Some(prev.start);
        loop {
            match self.run(host, 1) {
                Exit::Budget => {}
                Exit::Unhandled(u) => {
                    self.backward_entry = None;
                    return Err(BackwardRefusal::HandlerFailed(u.error.to_string()));
                }
                other => {
                    self.backward_entry = None;
                    return Err(BackwardRefusal::HandlerFailed(format!("{other:?}")));
                }
            }
            let back = self.frames.len() == depth && self.frames.last().is_some_and(|f| f.pc == prev.start);
            if back && self.backward_entry.is_none() {
                return Ok(BackStep::RanBackwardHandler(callee.name.clone()));
            }
        }
    }
}
