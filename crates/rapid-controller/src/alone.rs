//! A task run alone: a system of one task whose program no system input or output
//! operates (a module, a folder, a `.pgf`, a backup of one task). Nothing needs the
//! task cut at statements then, so its VM runs in slices of instructions
//! ([`rapid_vm::Vm::run`]) with the shared state handed in once per slice: as fast as
//! the interpreter itself.
//!
//! The clock of a task alone: a wait moves it by the wait's length; what the task
//! computes before a wait takes no time (times worked out by hand from a program's
//! waits stay exact); a slice computed without waiting (a loop polling a flag a trap
//! sets) and the restart of a cycle move it by the instructions' nominal time
//! ([`INSTRUCTION_TIME`] each), so timers come and a time bound ends such a loop.
//! Several tasks are charged by the statement instead (`schedule.rs`).

use rapid_vm::{Exit, Host};

use crate::schedule::{Controller, State, SystemExit, INSTRUCTION_TIME};
use crate::task::TaskEnd;

impl Controller {
    /// Whether the system is one task run alone: one task, no system inputs or outputs,
    /// the program running (a stop or a step under way runs it a statement at a time).
    pub fn runs_alone(&self) -> bool {
        self.tasks.len() == 1 && !self.ops.system_signals && self.program_state() == crate::ops::ProgramState::Running
    }

    /// Runs the task alone for at most `budget` instructions.
    pub(crate) fn run_alone(&mut self, host: &mut dyn Host, budget: u64) -> SystemExit {
        match self.tasks[0].state {
            State::Ended(_) => return SystemExit::Ended,
            // The caller moved the clock on over the wait (or a wait that re-checks
            // looks again).
            State::Waiting { .. } => self.tasks[0].state = State::Ready,
            State::Ready => {}
        }
        let time = self.time;
        let vm = &mut self.tasks[0].loaded.vm;
        let charged = *self.charged.get_or_insert(vm.steps);
        vm.time = time;
        vm.exchange_shared(&mut self.shared);
        let exit = vm.run(host, budget);
        vm.exchange_shared(&mut self.shared);
        let (steps, rechecks) = (vm.steps, vm.wait_rechecks);
        // A built-in that waited on the outside world (a socket) moved the task's clock.
        self.time = self.time.max(vm.time);
        self.steps = steps;
        // StopMove \AllMotionTasks and the like ask the controller (no other task answers).
        self.serve_request(host);
        let computed = steps.saturating_sub(charged) as f64 * INSTRUCTION_TIME;
        match exit {
            Exit::Budget => {
                self.charge(steps, computed);
                SystemExit::Budget
            }
            Exit::Wait(seconds) => {
                self.charged = Some(steps);
                let epoch = self.epoch();
                self.tasks[0].state = State::Waiting { until: self.time + seconds, rechecks, epoch };
                SystemExit::Wait(seconds)
            }
            Exit::Done | Exit::CycleEnded => {
                let end = if exit == Exit::Done { TaskEnd::Done } else { TaskEnd::CycleEnded };
                let state = self.cycle_end(0, end);
                if state == State::Ready {
                    // The next cycle starts: the last one's computing took its time.
                    self.charge(steps, computed);
                }
                self.settle(state)
            }
            // The STOP event routines run when the program stops, also at a warm start
            // (the run ends there).
            Exit::Stopped => {
                self.tasks[0].state = State::Ended(TaskEnd::Stopped);
                self.run_stop_routines(0, host);
                let state = self.tasks[0].state.clone();
                self.settle(state)
            }
            Exit::Unhandled(unhandled) => self.settle(State::Ended(TaskEnd::Failed(unhandled))),
        }
    }

    /// The clock moves on by `computed` seconds of computing, charged up to `steps`.
    fn charge(&mut self, steps: u64, computed: f64) {
        self.time += computed;
        self.charged = Some(steps);
    }

    /// The task stands at `state`: running on, or ended (and the run with it).
    fn settle(&mut self, state: State) -> SystemExit {
        let ended = matches!(state, State::Ended(_));
        self.tasks[0].state = state;
        if !ended {
            return SystemExit::Budget;
        }
        self.after_end(0);
        SystemExit::Ended
    }
}
