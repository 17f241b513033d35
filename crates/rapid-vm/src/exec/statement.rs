//! Running a task a basic step at a time, for the scheduler of a system of tasks.

use super::{Exit, Vm};

/// Instructions [`Vm::run_statement`] runs at most before giving way to the other tasks.
const MAX_STATEMENT_STEPS: u32 = 10_000;

impl Vm {
    /// Runs the task to the start of its next statement (the manual's "basic step",
    /// §1.20: tasks at one level take turns a basic step each), or to a wait, a stop or
    /// the end. A statement is never cut between its reads and writes, so two tasks
    /// adding to one shared persistent both count. A statement that runs on past
    /// `MAX_STATEMENT_STEPS` instructions (a function looping) gives way there.
    pub fn run_statement(&mut self, host: &mut dyn crate::host::Host) -> Exit {
        for _ in 0..MAX_STATEMENT_STEPS {
            let exit = self.run(host, 1);
            // A debugger's stop at an error ends the statement where it stands.
            if exit != Exit::Budget || self.at_statement_start() || self.error_stop_waits() {
                return exit;
            }
        }
        Exit::Budget
    }

    /// The top frame stands at the first instruction of one of its statements.
    fn at_statement_start(&self) -> bool {
        let Some(frame) = self.frames.last() else { return true };
        let stmts = &frame.code.stmts;
        let at = stmts.partition_point(|s| s.start < frame.pc);
        stmts.get(at).is_some_and(|s| s.start == frame.pc)
    }
}
