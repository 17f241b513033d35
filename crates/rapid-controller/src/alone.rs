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

/// What is left of a wait after the caller moved the clock over it by the length the
/// wait asked for: the rounding of adding that length to the clock, not a wait.
const MAX_CLOCK_ERROR: f64 = 1e-12;

impl Controller {
    /// Whether the system is one task run alone: one task, no system inputs or outputs,
    /// the program running (a stop or a step under way runs it a statement at a time),
    /// and no breakpoint set nor API step under way (the scheduler looks for those
    /// before each statement; a slice would run past them).
    pub fn runs_alone(&self) -> bool {
        self.tasks.len() == 1
            && !self.ops.system_signals
            && !self.watch.is_active()
            && self.program_state() == crate::ops::ProgramState::Running
    }

    /// The bound on [`Controller::steps`] the caller ends the run at (`--max-steps`):
    /// a task alone is not charged the computing of the slice that passed it, so the
    /// run ends at the clock of the slice before, as `rapid run` has always said.
    pub fn set_step_bound(&mut self, max: Option<u64>) {
        self.step_bound = max;
    }

    /// Runs the task alone for at most `budget` instructions.
    pub(crate) fn run_alone(&mut self, host: &mut dyn Host, budget: u64) -> SystemExit {
        match self.tasks[0].state {
            State::Ended(_) => return SystemExit::Ended,
            // The VM takes a wait it is resumed from as over: until the clock has
            // reached its end (or, for a wait that re-checks, the shared state changed)
            // the task still waits.
            State::Waiting { until, rechecks, epoch } => {
                let left = until - self.time;
                if left > MAX_CLOCK_ERROR && !(rechecks && epoch != self.epoch()) {
                    return SystemExit::Wait(left);
                }
                self.tasks[0].state = State::Ready;
            }
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
                if self.step_bound.is_none_or(|max| steps <= max) {
                    self.charge(steps, computed);
                }
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

#[cfg(test)]
mod tests {
    use rapid_vm::RecordingHost;

    use crate::test_support::one_task as alone;
    use crate::{Controller, SystemExit};

    /// Runs to the end, each wait moved over whole; the exits seen.
    fn run(controller: &mut Controller, host: &mut RecordingHost, budget: u64) -> Vec<SystemExit> {
        let mut exits = Vec::new();
        for _ in 0..10_000 {
            let exit = controller.run(host, budget);
            exits.push(exit);
            match exit {
                SystemExit::Wait(seconds) => controller.advance(seconds),
                SystemExit::Budget => {}
                SystemExit::Ended | SystemExit::Stopped => return exits,
            }
        }
        panic!("the run did not end");
    }

    #[test]
    fn computing_before_a_wait_is_free_and_a_slice_without_one_is_charged() {
        // 1000 additions, then a wait of 0.25 s: the clock reads the wait alone.
        let program = "MODULE M\n  PROC main()\n    VAR clock k;\n    VAR num n;\n    ClkStart k;\n    \
                       FOR i FROM 1 TO 1000 DO\n      n := n + i;\n    ENDFOR\n    WaitTime 0.25;\n    \
                       TPWrite \"at \" \\Num:=ClkRead(k\\HighRes);\n  ENDPROC\nENDMODULE";
        let mut c = alone(program);
        assert!(c.runs_alone());
        let mut host = RecordingHost::default();
        let exits = run(&mut c, &mut host, 1 << 16);
        assert_eq!(exits, [SystemExit::Wait(0.25), SystemExit::Ended]);
        assert_eq!(host.lines, ["at 0.25"]);
        // Counted in instructions: the loop alone runs more than its 1000 statements.
        assert!(c.steps > 2000, "{}", c.steps);

        // In slices of 100 instructions the loop is cut: each slice it computes without
        // waiting moves the clock by the nominal instruction time, which ClkRead sees.
        let mut c = alone(program);
        let mut host = RecordingHost::default();
        let exits = run(&mut c, &mut host, 100);
        let budgets = exits.iter().filter(|e| **e == SystemExit::Budget).count() as u64;
        assert!(budgets >= 20, "{exits:?}");
        let charged = (c.time - 0.25) / super::INSTRUCTION_TIME;
        assert!((charged - (100 * budgets) as f64).abs() < 1.0, "{} {budgets}", c.time);
    }
}
