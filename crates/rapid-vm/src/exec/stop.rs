//! Program stop and start as controller operations (the pendant's stop and start
//! buttons, a PLC's system inputs), as opposed to the Stop instruction: the task stops
//! between two instructions and starts again where it stood.
//!
//! At the stop (§1.11) queued interrupts are discarded except safe ones, and events
//! while stopped are dropped unless their interrupt is safe; the robot stops on its
//! path (StopMove's machinery). At the start the events of the stop are looked at once
//! more (timers that came due, signal changes) under the stop's rules, the robot goes
//! on along its path, a wait under way keeps the time it still had, and the queued
//! safe interrupts run first.

use super::{Exit, Unhandled, Vm};
use crate::value::Value;

/// Instructions an event routine run at a stop may take.
const MAX_EVENT_ROUTINE_STEPS: u64 = 10_000_000;

impl Vm {
    /// Whether the task stands between two RAPID instructions (or has no routine
    /// running), where a program stop may take effect.
    pub fn at_instruction_boundary(&self) -> bool {
        let Some(top) = self.frames.last() else { return true };
        top.code.stmt_at(top.pc).is_some_and(|s| s.start == top.pc)
    }

    /// Whether the task is stopped by [`Vm::program_stopped`].
    pub fn is_program_stopped(&self) -> bool {
        self.resources.interrupts.stop.is_some()
    }

    /// The program stops now (`self.time`): the interrupt queue keeps its safe
    /// interrupts only, and a robot moving stops on its path.
    pub fn program_stopped(&mut self, host: &mut dyn crate::host::Host) {
        if self.is_program_stopped() {
            return;
        }
        // A robot StopMove holds already stays held: the program's StartMove releases
        // it, not the start.
        let pause_robot = !self.extension_held();
        if pause_robot {
            self.call_motion_builtin("StopMove", &[Value::Absent, Value::Absent], host);
        }
        self.resources.interrupts.program_stopped(self.time, pause_robot);
    }

    /// The program starts again now (`self.time`) where it stood. The events of the
    /// stop are taken first (timers due, signal changes: safe interrupts queue, the
    /// others are dropped), then the robot goes on along its path and a wait under way
    /// is moved on by the time the program stood. The caller hands the shared state in
    /// (the signal changes are there).
    // uncertain: a WaitTime (and a \MaxTime of a wait) keeps the time it still had at
    // the stop, as the robot's path does; the manual does not say.
    pub fn program_started(&mut self, host: &mut dyn crate::host::Host) {
        let Some(stop) = self.resources.interrupts.stop else { return };
        let now = self.time;
        self.resources.interrupts.catch_up_timers(now);
        if self.resources.interrupts.active() {
            self.poll_interrupts();
        }
        self.resources.interrupts.program_started();
        let stood = (now - stop.since).max(0.0);
        if stop.paused_robot {
            self.call_motion_builtin("StartMove", &[Value::Absent], host);
        }
        if let Some((depth, pc, started)) = self.resources.waiting {
            self.resources.waiting = Some((depth, pc, started + stood));
        }
    }

    /// StopMove, StartMove or StopMoveReset on this task's robot, asked by another
    /// task's `\AllMotionTasks` through the controller.
    pub fn motion_for_another_task(&mut self, name: &str, host: &mut dyn crate::host::Host) {
        let args: &[Value] = if name == "StopMove" { &[Value::Absent, Value::Absent] } else { &[Value::Absent] };
        self.call_motion_builtin(name, args, host);
    }

    /// A step (FWD) of the stopped program begins now (`self.time`): a wait under way
    /// goes on with the time it still had, and the robot the stop held goes on along
    /// its path for the instruction. Interrupts stay as at the stop: no trap runs, only
    /// safe interrupts queue.
    // uncertain: the step lets the robot go on with what the stopped path still had, as
    // a start would; the manual does not say how far the robot goes in one step.
    pub fn step_started(&mut self, host: &mut dyn crate::host::Host) {
        let Some(stop) = self.resources.interrupts.stop else { return };
        let stood = (self.time - stop.since).max(0.0);
        if let Some((depth, pc, started)) = self.resources.waiting {
            self.resources.waiting = Some((depth, pc, started + stood));
        }
        if stop.paused_robot && self.extension_held() {
            self.call_motion_builtin("StartMove", &[Value::Absent], host);
        }
    }

    /// The step is over: the program stands stopped again from now, its robot
    /// stopped on its path.
    pub fn step_ended(&mut self, host: &mut dyn crate::host::Host) {
        let now = self.time;
        let Some(stop) = self.resources.interrupts.stop.as_mut() else { return };
        stop.since = now;
        if stop.paused_robot && !self.extension_held() {
            self.call_motion_builtin("StopMove", &[Value::Absent, Value::Absent], host);
        }
    }

    /// Runs a motion built-in (StopMove, StartMove) as the controller; it cannot fail
    /// for the arguments given.
    fn call_motion_builtin(&mut self, name: &str, args: &[Value], host: &mut dyn crate::host::Host) {
        if let Some(id) = self.builtins.lookup(name) {
            let _ = self.run_builtin(id, args, host);
        }
    }

    /// Runs the procedure `name` (event routine of system event `event`) on top of the
    /// stopped program, which afterwards stands where it stood. Interrupts wait while
    /// it runs. Err with the error no handler took; Ok(false) when there is no such
    /// procedure.
    // uncertain: an event routine at a program stop runs without traps (they wait for
    // the start); the manual does not say.
    pub fn run_event_routine_in_place(
        &mut self,
        host: &mut dyn crate::host::Host,
        name: &str,
        event: u8,
    ) -> Result<bool, Unhandled> {
        let Some(&idx) = self.procs_by_name.get(&name.to_lowercase()) else { return Ok(false) };
        let Some(code) = self.routines.get(idx as usize).cloned().flatten() else { return Ok(false) };
        let depth = self.frames.len();
        match self.frames.last() {
            None => self.start(code),
            Some(top) => {
                let resume = top.pc;
                self.push_frame(code, Vec::new());
                let frame = self.frame_mut();
                frame.return_to = Some(resume);
                frame.interrupted = true;
            }
        }
        let disabled = std::mem::replace(&mut self.resources.interrupts.disabled, true);
        self.resources.tasks.event = event;
        let mut outcome = Ok(true);
        for _ in 0..MAX_EVENT_ROUTINE_STEPS {
            match self.run(host, 1) {
                Exit::Wait(seconds) => self.time += seconds,
                Exit::Budget if self.frames.len() > depth => {}
                Exit::Unhandled(unhandled) => {
                    outcome = Err(unhandled);
                    break;
                }
                _ => break,
            }
        }
        self.resources.tasks.event = 0;
        self.resources.interrupts.disabled = disabled;
        outcome
    }
}
