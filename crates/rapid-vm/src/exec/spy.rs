//! The executor's side of SpyStart/SpyStop (manual §1.18 "执行的记录"): while a log
//! is open, instructions run one at a time on the general path, and every statement
//! that starts leaves one line in the log when it ends — its source text, the time it
//! was entered and left, and whether it was ready, waited or raised an error. A call
//! statement stays open while the routine it calls runs, so its line follows the
//! callee's lines and its time includes theirs.

use super::{Exit, RapidError, Vm};
use crate::builtins::spy::SpyCode;

/// A statement being logged.
#[derive(Debug)]
pub(super) struct SpyOpen {
    /// How many frames were on the stack when it started (its frame is the last).
    depth: usize,
    text: String,
    time_in: f64,
    waited: bool,
}

impl Vm {
    /// Executes one instruction, logging statements as they start and end.
    pub(super) fn spy_step(&mut self, host: &mut dyn crate::host::Host) -> Result<Option<Exit>, RapidError> {
        let depth = self.frames.len();
        self.spy_close_above(depth);
        if let Some(text) = self.statement_starting_here() {
            self.spy_close_at(depth, SpyCode::Ready);
            self.spy_open.push(SpyOpen { depth, text, time_in: self.time, waited: false });
        }
        let result = self.step(host);
        match &result {
            Err(_) => self.spy_close_at(depth, SpyCode::Error),
            Ok(Some(Exit::Wait(_))) => {
                if let Some(open) = self.spy_open.last_mut().filter(|o| o.depth == depth) {
                    open.waited = true;
                }
            }
            Ok(Some(_)) => self.spy_close_above(0),
            Ok(None) => {}
        }
        result
    }

    /// The source text of the statement that starts at the top frame's pc, if one does.
    fn statement_starting_here(&self) -> Option<String> {
        let frame = self.frames.last()?;
        let stmt = frame.code.stmt_at(frame.pc).filter(|s| s.start == frame.pc)?;
        let text = self.modules.source_text(frame.code.file)?;
        let source = text.get(stmt.span.start as usize..stmt.span.end as usize)?;
        Some(source.lines().next().unwrap_or("").to_string())
    }

    /// Ends the statements of frames that have returned (deeper than `depth`).
    fn spy_close_above(&mut self, depth: usize) {
        while self.spy_open.last().is_some_and(|o| o.depth > depth) {
            self.spy_close_last(SpyCode::Ready);
        }
    }

    /// Ends the statement open in the frame at `depth`, if any.
    fn spy_close_at(&mut self, depth: usize, code: SpyCode) {
        self.spy_close_above(depth);
        if self.spy_open.last().is_some_and(|o| o.depth == depth) {
            self.spy_close_last(code);
        }
    }

    fn spy_close_last(&mut self, code: SpyCode) {
        let Some(open) = self.spy_open.pop() else { return };
        let code = if code == SpyCode::Ready && open.waited { SpyCode::Wait } else { code };
        let task = self.resources.tasks.name().to_owned();
        self.resources.spy.record(&task, &open.text, open.time_in, code, self.time);
    }

    /// A log that ended (SpyStop, PP to Main) leaves nothing open behind.
    pub(super) fn spy_forget_if_stopped(&mut self) {
        if !self.resources.spy.is_active() {
            self.spy_open.clear();
        }
    }
}
