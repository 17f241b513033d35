//! A built-in that waits (WaitTime, WaitDI, WaitSyncTask…) answers
//! `StopKind::Repeat`: the statement starts over when the wait is looked at again, so
//! that a trap can run at the statement's start in between (§1.11: traps run during
//! waits). Starting over must not evaluate the arguments again: RAPID evaluates a
//! call's arguments once, when the call is made (`WaitTime f();` calls `f` once, however
//! many traps run during the wait). So the frame keeps the arguments the wait was first
//! called with, and when the statement starts over with the operand stack as it was,
//! the built-in is called again with them and the statement goes on after the call.
//!
//! A call is resumed this way only when the operand stack at the statement's start is
//! as it was when the call's arguments were taken off it (nothing of the statement
//! was left under them); a waiting function after other operands of an expression
//! starts its statement over as before, since those operands are gone.

use std::rc::Rc;

use crate::builtins::{BuiltinId, StopKind};
use crate::error::RapidError;
use crate::ir::Code;
use crate::value::Value;

use super::{Exit, Vm};

/// A waiting built-in call and what resuming it needs.
#[derive(Debug)]
pub(crate) struct Repeated {
    code: Rc<Code>,
    stmt_start: u32,
    call_pc: u32,
    /// The operand stack's length at the statement's start (the call's arguments
    /// taken off): a statement that starts over with another length is not resumed.
    stack_len: usize,
    id: BuiltinId,
    args: Vec<Value>,
}

type Outcome = Result<(Option<Value>, Option<f64>, StopKind), RapidError>;

impl Vm {
    /// After a built-in call at the top frame's pc: a wait that will start its
    /// statement over keeps its arguments; any other outcome forgets them.
    pub(super) fn remember_repeated(&mut self, outcome: &Outcome, id: BuiltinId, args: &[Value]) {
        let stack_len = self.storage.stack.len();
        let Some(frame) = self.frames.last_mut() else { return };
        if !matches!(outcome, Ok((_, _, StopKind::Repeat))) {
            // Every built-in call passes here (the fast loop's too): write only when
            // there is a record to forget.
            if frame.repeated.is_some() {
                frame.repeated = None;
            }
            return;
        }
        frame.repeated = frame.code.stmt_at(frame.pc).map(|s| {
            Box::new(Repeated {
                code: frame.code.clone(),
                stmt_start: s.start,
                call_pc: frame.pc,
                stack_len,
                id,
                args: args.to_vec(),
            })
        });
    }

    /// Resumes the top frame's waiting built-in when its statement is about to start
    /// over: the call runs again with its first arguments. `None` when there is none
    /// to resume (a record left behind by a statement that did not start over is
    /// dropped).
    pub(super) fn resume_repeated(
        &mut self,
        host: &mut dyn crate::host::Host,
    ) -> Option<Result<Option<Exit>, RapidError>> {
        let stack_len = self.storage.stack.len();
        let frame = self.frames.last_mut()?;
        let repeated = frame.repeated.as_ref()?;
        let same = Rc::ptr_eq(&repeated.code, &frame.code) && frame.pc == repeated.stmt_start;
        if !same || stack_len != repeated.stack_len {
            if !same {
                frame.repeated = None;
            }
            return None;
        }
        let repeated = frame.repeated.take()?;
        frame.pc = repeated.call_pc;
        let outcome = self.run_builtin(repeated.id, &repeated.args, host);
        self.remember_repeated(&outcome, repeated.id, &repeated.args);
        Some(self.after_builtin(outcome))
    }

    /// One instruction of the general path (the spy's when it is on), or the resumed
    /// wait when its statement starts over.
    pub(super) fn resume_or_step(&mut self, host: &mut dyn crate::host::Host) -> Result<Option<Exit>, RapidError> {
        match self.resume_repeated(host) {
            Some(resumed) => resumed,
            None if self.resources.spy.is_active() => self.spy_step(host),
            None => self.step(host),
        }
    }

    /// The fast loop, or the resumed wait when its statement starts over (counted as
    /// the one instruction it is: a budget of one runs it alone).
    pub(super) fn resume_or_run_fast(
        &mut self,
        remaining: &mut u64,
        host: &mut dyn crate::host::Host,
    ) -> super::fast::Fast {
        match self.resume_repeated(host) {
            Some(resumed) => {
                *remaining -= 1;
                self.steps += 1;
                super::fast::Fast::Called(resumed)
            }
            None => self.run_fast(remaining, host),
        }
    }
}
