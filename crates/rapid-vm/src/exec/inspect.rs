//! What a front end of the controller (a debugger, a web service) reads of a task
//! and asks of it besides running: the call stack with each frame's statement and
//! locals, the statements of the routines (to place line breakpoints), and PP to a
//! routine.
//! Nothing here runs in the executor's loop: it costs nothing when unused.

use std::rc::Rc;

use super::{Exit, Unhandled, Vm};
use crate::ir::Code;

/// One routine running in a task, as a debugger shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameView {
    pub routine: String,
    /// Index of the routine's file among the task's program sources.
    pub file: usize,
    /// The statement the frame stands at (for a caller: its call; before the first
    /// statement: that one), or the routine's span when it stands at none (its end).
    pub span: rapid_syntax::Span,
    /// Which handler of its routine it runs: 0 none, 1 BACKWARD, 2 ERROR, 3 UNDO.
    pub handler: u8,
    /// A TRAP routine an interrupt started.
    pub trap: bool,
}

impl Vm {
    /// The routines running, outermost (the entry routine) first.
    pub fn call_stack(&self) -> Vec<FrameView> {
        self.frames
            .iter()
            .map(|frame| {
                let (code, pc) = frame.position();
                FrameView {
                    routine: code.name.clone(),
                    file: code.file,
                    // Before its first statement (a routine's data being given its
                    // initial values) a frame stands at that statement.
                    span: code
                        .stmt_at(pc)
                        .or_else(|| code.stmts.iter().find(|s| s.start >= pc).copied())
                        .map_or(code.span, |s| s.span),
                    handler: frame.handler_type(),
                    trap: frame.interrupted,
                }
            })
            .collect()
    }

    /// The parameters and routine data of frame `frame` (0: the outermost), by name
    /// in declaration order; a VAR, INOUT or PERS parameter shows the value of the
    /// data it refers to. None when there is no such frame.
    pub fn frame_locals(&self, frame: usize) -> Option<Vec<(String, crate::value::Value)>> {
        let f = self.frames.get(frame)?;
        let locals = f.code.local_names.iter().filter_map(|(name, slot)| {
            let value = self.storage.stack.get((f.base + slot) as usize)?;
            let value = match value {
                crate::value::Value::Ref(place) => self.storage.get(place).ok()?.clone(),
                other => other.clone(),
            };
            Some((name.clone(), value))
        });
        Some(locals.collect())
    }

    /// Parameter or routine datum `name` of frame `frame` (0: the outermost), to be
    /// written by a debugger: a parameter passed by value and routine data are the
    /// frame's own values; a VAR, INOUT or PERS parameter is the data its argument
    /// names, since updating it updates the argument (§1.5). None when the frame has
    /// no such name; `Some(Err)` says why it cannot be written (a CONST, an optional
    /// parameter not present, a switch, an argument that no longer exists).
    pub fn frame_local_mut(&mut self, frame: usize, name: &str) -> Option<Result<&mut crate::value::Value, String>> {
        use crate::value::Value;
        let f = self.frames.get(frame)?;
        let &(ref declared, slot) = f.code.local_names.iter().find(|(n, _)| n.eq_ignore_ascii_case(name))?;
        if f.code.const_locals.contains(&slot) {
            return Some(Err(format!("`{declared}` is a CONST of the routine")));
        }
        let declared = declared.clone();
        let at = (f.base + slot) as usize;
        if let Value::Ref(place) = self.storage.stack.get(at)? {
            let place = (**place).clone();
            return Some(
                self.storage.get_mut(&place).map_err(|_| format!("the argument of `{declared}` no longer exists")),
            );
        }
        let value = self.storage.stack.get_mut(at)?;
        Some(match value {
            Value::Absent => Err(format!("the optional parameter `{declared}` is not present")),
            Value::SwitchOn => Err(format!("the switch `{declared}` has no value to set")),
            _ => Ok(value),
        })
    }

    /// How many routines are running.
    pub fn depth(&self) -> usize {
        self.frames.len()
    }

    /// The innermost routine and the instruction it is at.
    pub fn top_position(&self) -> Option<(&Code, u32)> {
        self.frames.last().map(|f| f.position())
    }

    /// The compiled routines (the modules loaded at run time among them).
    pub fn codes(&self) -> impl Iterator<Item = &Rc<Code>> {
        self.routines.iter().flatten()
    }

    /// "PP to Routine": the UNDO handlers of the routines running run (§1.13), then
    /// execution is set to start procedure `name`, which must take no parameters.
    /// Data keeps its values (unlike PP to Main). Ok(false) when there is no such
    /// procedure or it takes parameters.
    pub fn pp_to_routine(&mut self, host: &mut dyn crate::host::Host, name: &str) -> Result<bool, Unhandled> {
        let Some(&idx) = self.procs_by_name.get(&name.to_lowercase()) else { return Ok(false) };
        if self.routines.get(idx as usize).cloned().flatten().is_none_or(|code| code.n_params > 0) {
            return Ok(false);
        }
        if !self.frames.is_empty() {
            self.exiting = true;
            if self.continue_exit().is_none() {
                if let Exit::Unhandled(u) = self.run(host, u64::MAX) {
                    return Err(u);
                }
            }
        }
        Ok(self.start_routine(idx))
    }
}
