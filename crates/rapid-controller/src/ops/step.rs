//! Step mode (FWD step, §1.11): a stopped program runs one instruction of one NORMAL
//! task and stands stopped again, as the pendant's forward-step button (or a
//! debugger) asks.
//!
//! While stepping, the program counts as stopped for interrupts: no trap runs, events
//! of safe interrupts (`\SingleSafe`) are queued and all others are dropped; the safe
//! ones queued run first, in order, when continuous execution starts (§1.11 "安全中断").
//! A wait under way at the stop goes on with the time it still had; the robot goes on
//! along its path during the step and stops on it again after. RunMode reads
//! RUN_INSTR_FWD (or RUN_STEP_MOVE) while stepping, and a move stepped ends with the
//! robot at its target, its zone taken as a stop point
//! (`rapid_vm::builtins::controller::RunMode::moves_end_at_targets`).
// uncertain: the STOP event routines and the event-log entries of a stop and start
// (10150/10151) are not repeated for each step; the manual does not say.

use rapid_vm::builtins::controller::RunMode;
use rapid_vm::Host;

use super::ProgramState;
use crate::schedule::{Controller, State};
use crate::task::TaskKind;

impl Controller {
    /// One step of NORMAL task `task` of the stopped program. False when the program
    /// is not stopped, the motors are off, or `task` is no NORMAL task still running.
    pub fn step_forward(&mut self, host: &mut dyn Host, task: usize) -> bool {
        self.step_forward_as(host, task, RunMode::InstrFwd)
    }

    /// [`Controller::step_forward`] in run mode `mode`: a forward step
    /// (RUN_INSTR_FWD) or a move step (RUN_STEP_MOVE).
    pub fn step_forward_as(&mut self, host: &mut dyn Host, task: usize, mode: RunMode) -> bool {
        if self.ops.state() != ProgramState::Stopped || self.ops.motors_off {
            return false;
        }
        let Some(spec) = self.tasks.get(task).map(|t| &t.spec) else { return false };
        if spec.kind != TaskKind::Normal || matches!(self.tasks[task].state, State::Ended(_)) {
            return false;
        }
        self.set_run_mode(mode);
        // uncertain: the STEP event routines run as each step begins.
        for routine in self.hooks_of("STEP", task) {
            self.run_in_place(task, host, &routine, "STEP");
        }
        if matches!(self.tasks[task].state, State::Ended(_)) {
            return false;
        }
        let from_steps = self.tasks[task].loaded.vm.steps;
        self.ops.step_from = position(&self.tasks[task].loaded.vm);
        self.ops.state = Some(ProgramState::Stepping { task, from_steps });
        self.with_task(task, host, |vm, host| vm.step_started(host));
        // No trap runs in a step, so a wait under way goes on with the time it still
        // had even when a safe interrupt waits.
        let stood = self.time - self.ops.stopped_at;
        if let Some(State::Waiting { until, rechecks, epoch }) = self.ops.held.get_mut(task).and_then(Option::take) {
            self.tasks[task].state = State::Waiting { until: until + stood, rechecks, epoch };
        }
        self.note(format!("step of task {}", self.tasks[task].spec.name));
        true
    }

    /// The step ends once its task has run an instruction and stands at the next
    /// one (or has ended).
    pub(super) fn follow_step(&mut self, host: &mut dyn Host, task: usize, from_steps: u64) {
        let done = match &self.tasks[task].state {
            State::Ended(_) => true,
            State::Ready => self.statement_done(task, from_steps),
            _ => false,
        };
        // API hook: a step over or out goes on to its target depth.
        if !done || !self.step_target_reached(task) {
            return;
        }
        self.ops.state = Some(ProgramState::Stopped);
        self.ops.stopped_at = self.time;
        if matches!(self.tasks[task].state, State::Ready) {
            self.with_task(task, host, |vm, host| vm.step_ended(host));
        }
        self.note(format!("step of task {} done", self.tasks[task].spec.name));
    }
}

impl Controller {
    /// Whether the step of task `task` (which had run `from_steps` before) has run a
    /// whole statement and stands at the next one. A waiting statement that looks
    /// again (WaitDI, WaitUntil, a sync point) stands where it started between its
    /// looks: the step goes on until it has passed, as the step of a WaitTime lasts
    /// its wait.
    pub(crate) fn statement_done(&self, task: usize, from_steps: u64) -> bool {
        let vm = &self.tasks[task].loaded.vm;
        let repeats = vm.wait_rechecks && position(vm) == self.ops.step_from;
        vm.steps > from_steps && vm.at_instruction_boundary() && !repeats
    }
}

/// Where a task stands: its call depth and instruction.
fn position(vm: &rapid_vm::Vm) -> Option<(usize, u32)> {
    vm.top_position().map(|(_, pc)| (vm.depth(), pc))
}
