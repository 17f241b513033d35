//! The program operations a front end's API needs beyond the pendant's buttons
//! (`crate::api`): the program standing stopped at boot, PP to Main without a start,
//! PP to a routine. Kept apart from `ops.rs` so that the operations' own rules stay
//! in one place; these only move the program pointer and forget a held wait.

use rapid_tasks::SharedTaskingAccess;
use rapid_vm::Host;

use super::ProgramState;
use crate::schedule::{Controller, State};
use crate::task::{TaskEnd, TaskKind};

impl Controller {
    /// The program stands stopped, its program pointers where they are (at boot:
    /// at the entry routine), without the STOP event routines or a log entry: no
    /// program ran to be stopped.
    pub(crate) fn stand_stopped(&mut self) {
        self.ops.state = Some(ProgramState::Stopped);
        self.ops.stopped_at = self.time;
    }

    /// PP to Main of every NORMAL task of the stopped program (ended ones too: a new
    /// cycle may start), without starting it. Err names a task whose UNDO handlers or
    /// data initialisation failed (that task has ended with the error).
    pub(crate) fn pp_to_main_all(&mut self, host: &mut dyn Host) -> Result<(), String> {
        let normal: Vec<usize> =
            (0..self.tasks.len()).filter(|&i| self.tasks[i].spec.kind == TaskKind::Normal).collect();
        let mut failed = None;
        for idx in normal {
            let entry = self.tasks[idx].loaded.entry;
            let name = self.tasks[idx].spec.name.clone();
            let outcome = self.with_task(idx, host, |vm, host| {
                let outcome = vm.pp_to_main(host, entry);
                let reset = format!("The program pointer of task {name} was set to its entry routine.");
                vm.log_state(rapid_vm::events::PP_RESET, reset);
                outcome
            });
            self.pointer_moved(idx, outcome.map(|()| true), &mut failed);
        }
        self.note("PP to Main".to_owned());
        failed.map_or(Ok(()), Err)
    }

    /// PP to procedure `routine` in NORMAL task `idx` of the stopped program. Ok(false)
    /// when the task has no such procedure without parameters.
    pub(crate) fn pp_to_routine_in(&mut self, host: &mut dyn Host, idx: usize, routine: &str) -> Result<bool, String> {
        let outcome = self.with_task(idx, host, |vm, host| vm.pp_to_routine(host, routine));
        if matches!(outcome, Ok(false)) {
            return Ok(false);
        }
        let mut failed = None;
        self.pointer_moved(idx, outcome, &mut failed);
        self.note(format!("PP to routine {routine} in task {}", self.tasks[idx].spec.name));
        failed.map_or(Ok(true), Err)
    }

    /// Whether task `idx` waits inside an instruction that moved its program counter
    /// on before waiting (a plain wait, not one re-run until its condition holds):
    /// now, or held at the program's stop.
    pub(crate) fn waits_in_instruction(&self, idx: usize) -> bool {
        let held = self.ops.held.get(idx).is_some_and(|h| matches!(h, Some(State::Waiting { .. })));
        let waiting = held || matches!(self.tasks[idx].state, State::Waiting { .. });
        waiting && !self.tasks[idx].loaded.vm.wait_rechecks
    }

    /// Task `idx`'s program pointer was moved: it is ready to run from there (the
    /// wait it had at the stop is forgotten), or it ended with the error of its UNDO
    /// handlers.
    fn pointer_moved(&mut self, idx: usize, outcome: Result<bool, rapid_vm::Unhandled>, failed: &mut Option<String>) {
        let name = self.tasks[idx].spec.name.clone();
        self.tasks[idx].state = match outcome {
            Ok(_) => {
                self.shared.tasking_mut().set_executing(&name, true);
                State::Ready
            }
            Err(unhandled) => {
                *failed = Some(format!("task {name}: {}", unhandled.error));
                State::Ended(TaskEnd::Failed(unhandled))
            }
        };
        if let Some(slot) = self.ops.held.get_mut(idx) {
            *slot = None;
        }
    }
}
