//! Controller operations on the program (the NORMAL tasks): stop, start, start from
//! main, motors on and off — as the pendant's buttons, a debugger or a PLC's system
//! inputs (EIO.cfg `SYSSIG_IN`) ask for them — and the system outputs (`SYSSIG_OUT`)
//! that show the controller's state.
//!
//! A stop takes effect at the next instruction boundary of each NORMAL task: a task
//! computing runs on to the start of its next instruction; a task waiting stops at
//! once and keeps the wait it still had. Each stopped task's VM discards its queued
//! interrupts except safe ones and stops its robot on its path (`Vm::program_stopped`),
//! its STOP (QSTOP for a quick stop) event routines run, and the event log gets 10151.
//! A start runs the RESTART event routines, logs 10150, and each task goes on where
//! it stood: safe interrupts queued meanwhile first, then the rest of its wait (moved
//! on by the time it stood), its robot along the rest of its path. STATIC and
//! SEMISTATIC tasks are not stopped.

use rapid_config::eio::{Eio, SysAction, SysStatus};
use rapid_robot::RobotResources;
use rapid_signals::SharedIoAccess;
use rapid_tasks::SharedTaskingAccess;
use rapid_vm::builtins::controller::RunMode;
use rapid_vm::Host;

use crate::schedule::{Controller, State};
use crate::task::{TaskEnd, TaskKind};

/// Instructions a task computing may run on to reach an instruction boundary before
/// the stop takes it where it is.
const MAX_SETTLE_STEPS: u64 = 100_000;

/// How the program is to stop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopKind {
    /// Stop (and SoftStop): at the next instruction; STOP event routines.
    Stop,
    /// QuickStop: as Stop, with the QSTOP event routines.
    // uncertain: a quick stop brakes the robot harder; the stopping distance is not
    // modelled (the robot stands where it was at the stop), so only the event differs.
    Quick,
    /// StopCycle: when the cycle ends (`rapid run` runs one cycle, so at its end).
    Cycle,
}

/// How the program is started.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StartMode {
    /// CONT: continuous.
    Continuous,
    /// CYCLE: one cycle.
    Cycle,
}

/// Where the program stands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ProgramState {
    Running,
    /// A stop asked for: tasks run on to their next instruction boundary.
    Stopping {
        kind: StopKind,
        steps: u64,
    },
    Stopped,
    /// A step (FWD) of the stopped program: NORMAL task `task` runs one instruction
    /// (it had run `from_steps` before), then the program stands stopped again.
    Stepping {
        task: usize,
        from_steps: u64,
    },
}

/// A system input or output resolved to its signal.
#[derive(Debug, Clone)]
struct SysInput {
    id: u32,
    action: SysAction,
    arg: Option<String>,
}

#[derive(Debug, Clone)]
struct SysOutput {
    id: u32,
    status: SysStatus,
    /// The task (by index) a TaskExecuting or Error output watches, or the task that
    /// moves the unit of a MechUnit… output; None: any task (Error), every unit
    /// (MechUnit… without `-Arg1`).
    task: Option<usize>,
}

/// The operations' state inside the controller.
#[derive(Debug, Default)]
pub struct Operations {
    pub(crate) state: Option<ProgramState>,
    inputs: Vec<SysInput>,
    outputs: Vec<SysOutput>,
    /// How much of the I/O change log the system inputs have seen.
    seen_changes: usize,
    /// Each NORMAL task's wait at the stop, resumed (moved on) at the start.
    held: Vec<Option<State>>,
    /// The time of the stop.
    stopped_at: f64,
    /// Where the task of the step under way stood when it began (call depth and
    /// instruction): a waiting statement repeated there has not run yet (`ops/step.rs`).
    pub(crate) step_from: Option<(usize, u32)>,
    /// The motors are off (they are on from power on: `rapid run` is in automatic mode).
    motors_off: bool,
    /// The operating mode is automatic (AutoOn).
    pub auto: bool,
    /// Execution errors shown (Error), by task; ResetError clears them.
    errors_shown: Vec<bool>,
    /// Failed tasks whose error has been shown once.
    errors_seen: Vec<bool>,
    /// A stop at the end of the cycle is asked for.
    stop_at_cycle_end: bool,
    /// Event routines by system event (`STOP`, `QSTOP`, `RESTART`, `START`), by task.
    hooks: Vec<(String, Vec<Vec<String>>)>,
    /// What the operations did, for the run's report: (time, text).
    pub journal: Vec<(f64, String)>,
    /// The outputs may show something else now (set at each change of state).
    pub(crate) outputs_stale: bool,
    /// An output shows whether a robot moves (MechUnitNotMoving): the outputs are
    /// looked at whenever the controller is, and the clock stops where a move ends.
    watch_motion: bool,
    /// Which tasks' robots stood still when the outputs were last shown.
    still_shown: Vec<bool>,
    /// The I/O configuration has system inputs or outputs: the program is operated
    /// between statements, so even a task alone runs a statement at a time.
    pub(crate) system_signals: bool,
}

impl Operations {
    fn state(&self) -> ProgramState {
        self.state.unwrap_or(ProgramState::Running)
    }
}

impl Controller {
    /// The program's state.
    pub fn program_state(&self) -> ProgramState {
        self.ops.state()
    }

    /// What the operations did: (controller time, what).
    pub fn journal(&self) -> &[(f64, String)] {
        &self.ops.journal
    }

    /// The event routines of system event `shelf` (`STOP`, `QSTOP`, `RESTART`,
    /// `START`), each task's by index, for the operations to run.
    pub fn set_event_routines(&mut self, shelf: &str, routines: Vec<Vec<String>>) {
        self.ops.hooks.retain(|(s, _)| s != shelf);
        self.ops.hooks.push((shelf.to_owned(), routines));
    }

    /// The system inputs and outputs of the I/O configuration, resolved against the
    /// controller's I/O system and tasks. Err names what cannot be resolved (a task
    /// the system does not have).
    pub fn configure_system_signals(&mut self, eio: &Eio, auto: bool) -> Result<(), String> {
        self.ops.auto = auto;
        self.ops.system_signals = !eio.sys_inputs.is_empty() || !eio.sys_outputs.is_empty();
        self.ops.errors_shown = vec![false; self.tasks.len()];
        self.ops.errors_seen = vec![false; self.tasks.len()];
        let Some(io) = self.io_system() else { return Ok(()) };
        let mut inputs = Vec::new();
        // An input that cannot operate the controller is left out: ResetEstop (a virtual
        // run has no emergency stop to reset) and the actions not simulated (the
        // configuration warned of them).
        let operates = |action: SysAction| !matches!(action, SysAction::ResetEstop | SysAction::NotSimulated(_));
        for input in eio.sys_inputs.iter().filter(|input| operates(input.action)) {
            let Some(id) = io.id(&input.signal) else { continue };
            inputs.push(SysInput { id, action: input.action, arg: input.arg1.clone() });
        }
        let mut outputs = Vec::new();
        // The statuses not simulated are never set (the configuration warned of them).
        for output in eio.sys_outputs.iter().filter(|output| !matches!(output.status, SysStatus::NotSimulated(_))) {
            let Some(id) = io.id(&output.signal) else { continue };
            let task = match (&output.unit, &output.task) {
                (Some(unit), _) => Some(self.unit_task(unit, output)?),
                (None, None) => None,
                (None, Some(name)) => match self.tasks.iter().position(|t| t.spec.name.eq_ignore_ascii_case(name)) {
                    Some(idx) => Some(idx),
                    None => {
                        return Err(format!(
                            "system output `{}` (line {}) names task `{name}`, which the system does not have",
                            output.signal, output.line
                        ))
                    }
                },
            };
            outputs.push(SysOutput { id, status: output.status, task });
        }
        self.ops.seen_changes = self.shared.io().change_count();
        self.ops.watch_motion = outputs.iter().any(|o| o.status == SysStatus::MechUnitNotMoving);
        self.ops.inputs = inputs;
        self.ops.outputs = outputs;
        self.ops.outputs_stale = true;
        Ok(())
    }

    /// The task that moves mechanical unit `unit` (a robot, `ROB_n`) of a MechUnit…
    /// system output.
    fn unit_task(&self, unit: &str, output: &rapid_config::eio::syssig::SysOutput) -> Result<usize, String> {
        let number = unit.to_ascii_uppercase().strip_prefix("ROB_").and_then(|n| n.parse::<usize>().ok());
        let robot = self.shared.tasking().robots().into_iter().find(|&(n, _)| Some(n) == number);
        if let Some((_, task)) = robot {
            return Ok(task);
        }
        let external = self.tasks.iter().any(|t| t.loaded.vm.resources().robot().external.find(unit).is_some());
        let status = rapid_config::eio::syssig::status_name(output.status);
        Err(if external {
            format!(
                "system output `{}` (line {}): {status} of external unit `{unit}` is not supported yet (robots only)",
                output.signal, output.line
            )
        } else {
            format!(
                "system output `{}` (line {}) names mechanical unit `{unit}`, which the system does not have",
                output.signal, output.line
            )
        })
    }

    /// The earliest time after now that a watched robot stands still (a system output
    /// shows it): the controller must look at its outputs then.
    pub(crate) fn next_motion_end(&self) -> Option<f64> {
        if !self.ops.watch_motion {
            return None;
        }
        let ends =
            self.tasks.iter().map(|t| t.loaded.vm.resources().robot().still_from()).filter(|&end| end > self.time);
        ends.min_by(f64::total_cmp)
    }

    /// Whether system inputs may operate the controller (the run then follows the
    /// I/O system's events even while the program is stopped).
    pub fn has_system_inputs(&self) -> bool {
        !self.ops.inputs.is_empty()
    }

    /// Whether a Stop instruction in task `idx` stops the program, to be started again
    /// where it stands, rather than ending the task: system inputs may start it, and it
    /// is the only NORMAL task still running.
    // uncertain: Stop without \AllMoveTasks stops its own task only; with other NORMAL
    // tasks running the task ends as it does without system inputs.
    pub(crate) fn stop_instruction_holds(&self, idx: usize) -> bool {
        self.has_system_inputs()
            && self.tasks[idx].spec.kind == TaskKind::Normal
            && self.ops.state() == ProgramState::Running
            && self.stopped_tasks() == [idx]
    }

    /// A Stop instruction stopped the program ([`Controller::stop_instruction_holds`]).
    pub(crate) fn stopped_by_instruction(&mut self, host: &mut dyn Host) {
        self.complete_stop(host, StopKind::Stop);
    }

    /// Asks the program to stop; it stops at the next instruction boundary of each
    /// NORMAL task, during [`Controller::run`].
    pub fn stop(&mut self, kind: StopKind) {
        if self.ops.state() != ProgramState::Running {
            return;
        }
        if kind == StopKind::Cycle {
            self.ops.stop_at_cycle_end = true;
            self.note("stop at the end of the cycle asked for".to_owned());
            return;
        }
        self.ops.state = Some(ProgramState::Stopping { kind, steps: 0 });
    }

    /// Starts the stopped program where it stands. False when it is not stopped (a
    /// start of a running program does nothing) or the motors are off.
    pub fn start(&mut self, host: &mut dyn Host, mode: StartMode) -> bool {
        if self.ops.state() != ProgramState::Stopped || self.ops.motors_off {
            return false;
        }
        // uncertain: `rapid run` runs one cycle; CYCLE and CONT differ only in what
        // happens at the end of main, which ends the run either way. A start from the
        // stop position runs the RESTART event routines (START is for a start from
        // main), as we remember the system parameters manual's table of events.
        let _ = mode;
        self.set_run_mode(RunMode::ContCycle);
        self.ops.state = Some(ProgramState::Running);
        let stood = self.time - self.ops.stopped_at;
        for idx in self.stopped_tasks() {
            let line = format!("Program execution in task {} has been started.", self.tasks[idx].spec.name);
            self.with_task(idx, host, |vm, _| vm.log_state(rapid_vm::events::PROGRAM_STARTED, line));
            for routine in self.hooks_of("RESTART", idx) {
                self.run_in_place(idx, host, &routine, "RESTART");
            }
            self.with_task(idx, host, |vm, host| vm.program_started(host));
            // The RESTART routines took time too: the wait goes on from now.
            let stood_until_now = self.time - self.ops.stopped_at;
            self.resume_wait(idx, stood_until_now);
        }
        self.note(format!("program started (stood {} s)", trim(stood)));
        true
    }

    /// PP to Main in every NORMAL task, then a start from main (START event routines).
    pub fn start_main(&mut self, host: &mut dyn Host) -> bool {
        if self.ops.state() != ProgramState::Stopped || self.ops.motors_off {
            return false;
        }
        self.set_run_mode(RunMode::ContCycle);
        self.ops.state = Some(ProgramState::Running);
        for idx in self.stopped_tasks() {
            let entry = self.tasks[idx].loaded.entry;
            let name = self.tasks[idx].spec.name.clone();
            let failed = self.with_task(idx, host, |vm, host| {
                vm.program_started(host);
                let outcome = vm.pp_to_main(host, entry);
                let reset = format!("The program pointer of task {name} was set to its entry routine.");
                vm.log_state(rapid_vm::events::PP_RESET, reset);
                let started = format!("Program execution in task {name} has been started.");
                vm.log_state(rapid_vm::events::PROGRAM_STARTED, started);
                outcome.err()
            });
            self.tasks[idx].state = match failed {
                Some(unhandled) => State::Ended(TaskEnd::Failed(unhandled)),
                None => State::Ready,
            };
            if let Some(slot) = self.ops.held.get_mut(idx) {
                *slot = None;
            }
            for routine in self.hooks_of("START", idx) {
                if let Err(unhandled) = self.run_event_routine(idx, host, &routine, event_number("START")) {
                    self.tasks[idx].state = State::Ended(TaskEnd::Failed(unhandled));
                }
            }
        }
        self.note("program started from main".to_owned());
        true
    }

    /// Whether the motors are on.
    pub fn motors_on(&self) -> bool {
        !self.ops.motors_off
    }

    /// Motors on (true) or off. Motors off stops a running program.
    // uncertain: motors off while the program runs stops it as a quick stop would
    // (the robot cannot move); the controller logs more than we do.
    pub fn set_motors(&mut self, on: bool) {
        self.ops.motors_off = !on;
        self.note(format!("motors {}", if on { "on" } else { "off" }));
        if !on && self.ops.state() == ProgramState::Running && self.any_normal_running() {
            self.ops.state = Some(ProgramState::Stopping { kind: StopKind::Quick, steps: 0 });
        }
    }

    /// Between instructions of [`Controller::run`]: the system inputs' rising edges,
    /// a stop under way, the system outputs.
    pub(crate) fn operate(&mut self, host: &mut dyn Host) {
        if !self.ops.inputs.is_empty() && self.io_event_due() {
            self.follow_inputs(host);
        }
        if let ProgramState::Stopping { kind, steps } = self.ops.state() {
            let settled = self.stopped_tasks().iter().all(|&idx| self.settled(idx));
            if settled || steps >= MAX_SETTLE_STEPS {
                self.complete_stop(host, kind);
            } else {
                self.ops.state = Some(ProgramState::Stopping { kind, steps: steps + 1 });
            }
        }
        if let ProgramState::Stepping { task, from_steps } = self.ops.state() {
            self.follow_step(host, task, from_steps);
        }
        if self.ops.watch_motion && self.motion_changed() {
            self.ops.outputs_stale = true;
        }
        if self.ops.outputs_stale && !self.ops.outputs.is_empty() {
            self.show_outputs();
        }
    }

    /// Whether the I/O system has something to do by now (a stimulus line, an order
    /// come due, a change the system inputs have not seen): only then is it advanced,
    /// as this is looked at between any two instructions.
    fn io_event_due(&self) -> bool {
        let io = self.shared.io();
        let now = self.time;
        let at = |front: Option<&(f64, u32, f64)>| front.is_some_and(|&(t, _, _)| t <= now);
        at(io.stimulus.front())
            || at(io.path_orders.front())
            || io.system.as_ref().and_then(|s| s.next_event_time()).is_some_and(|t| t <= now)
            || io.change_count() != self.ops.seen_changes
    }

    /// Whether NORMAL task `idx` may run an instruction now (not while the program is
    /// stopped, nor once it stands at a boundary while a stop is under way).
    pub(crate) fn may_run(&self, idx: usize) -> bool {
        if self.tasks[idx].spec.kind != TaskKind::Normal {
            return true;
        }
        match self.ops.state() {
            ProgramState::Running => true,
            ProgramState::Stopped => false,
            ProgramState::Stopping { .. } => !self.settled(idx),
            ProgramState::Stepping { task, .. } => task == idx,
        }
    }

    /// When the program is stopped: the next event that may start it (an I/O event),
    /// None when nothing can.
    pub(crate) fn next_operation(&mut self) -> Option<f64> {
        if self.ops.inputs.is_empty() {
            return None;
        }
        let mut io = rapid_signals::IoState::default();
        io.exchange_shared(self.shared.io_mut());
        let next = io.next_event_time();
        io.exchange_shared(self.shared.io_mut());
        next
    }

    fn settled(&self, idx: usize) -> bool {
        let task = &self.tasks[idx];
        match task.state {
            State::Ready => task.loaded.vm.at_instruction_boundary(),
            _ => true,
        }
    }

    /// How the program runs from now (RunMode: continuous, stepped forward or
    /// backward, move step), in every NORMAL task: the program runs in one mode, and
    /// the static and semistatic tasks run on continuously whatever it is.
    pub(crate) fn set_run_mode(&mut self, mode: RunMode) {
        for task in self.tasks.iter_mut().filter(|t| t.spec.kind == TaskKind::Normal) {
            task.loaded.vm.resources_mut().controller.run_mode = mode;
        }
    }

    /// NORMAL tasks that have not ended.
    fn stopped_tasks(&self) -> Vec<usize> {
        (0..self.tasks.len())
            .filter(|&i| self.tasks[i].spec.kind == TaskKind::Normal && !matches!(self.tasks[i].state, State::Ended(_)))
            .collect()
    }

    fn any_normal_running(&self) -> bool {
        !self.stopped_tasks().is_empty()
    }

    /// Every NORMAL task has ended and the controller lives on
    /// ([`Controller::set_lives_on`]): a running program stops there, with no STOP
    /// event routines (no task stands to run them), as the end of a cycle stops it.
    pub(crate) fn cycle_over(&mut self) {
        if self.ops.state() != ProgramState::Running {
            return;
        }
        self.ops.state = Some(ProgramState::Stopped);
        self.ops.stopped_at = self.time;
        self.ops.stop_at_cycle_end = false;
        self.note("program stopped: the cycle is over".to_owned());
    }

    /// Every NORMAL task stands at a boundary (or waits): the program stops.
    fn complete_stop(&mut self, host: &mut dyn Host, kind: StopKind) {
        self.ops.state = Some(ProgramState::Stopped);
        self.ops.stopped_at = self.time;
        self.ops.held.resize(self.tasks.len(), None);
        let shelf = if kind == StopKind::Quick { "QSTOP" } else { "STOP" };
        for idx in self.stopped_tasks() {
            self.ops.held[idx] = match self.tasks[idx].state {
                State::Waiting { .. } => Some(self.tasks[idx].state.clone()),
                _ => None,
            };
            let line =
                format!("Program execution in task {} has stopped: a stop was ordered.", self.tasks[idx].spec.name);
            self.with_task(idx, host, |vm, host| {
                vm.program_stopped(host);
                vm.log_state(rapid_vm::events::PROGRAM_STOPPED, line);
            });
            for routine in self.hooks_of(shelf, idx) {
                self.run_in_place(idx, host, &routine, shelf);
            }
        }
        self.note(format!("program stopped ({})", if kind == StopKind::Quick { "quick stop" } else { "stop" }));
    }

    /// Task `idx` goes on after a start: its wait resumes with the time it still had,
    /// or at once when a safe interrupt waits for its trap.
    fn resume_wait(&mut self, idx: usize, stood: f64) {
        let held = self.ops.held.get_mut(idx).and_then(Option::take);
        let interrupt_work = self.tasks[idx].loaded.vm.has_interrupt_work();
        let task = &mut self.tasks[idx];
        if matches!(task.state, State::Ended(_)) {
            return;
        }
        task.state = match held {
            Some(State::Waiting { until, rechecks, epoch }) if !interrupt_work => {
                State::Waiting { until: until + stood, rechecks, epoch }
            }
            _ => State::Ready,
        };
    }

    /// Runs an event routine on top of the stopped task; an error in it is the
    /// task's failure.
    fn run_in_place(&mut self, idx: usize, host: &mut dyn Host, routine: &str, shelf: &str) {
        let event = event_number(shelf);
        let outcome = self.with_task(idx, host, |vm, host| vm.run_event_routine_in_place(host, routine, event));
        if let Err(unhandled) = outcome {
            self.tasks[idx].state = State::Ended(TaskEnd::Failed(unhandled));
            self.note(format!("task {} failed in its {shelf} event routine {routine}", self.tasks[idx].spec.name));
        }
    }

    pub(crate) fn hooks_of(&self, shelf: &str, idx: usize) -> Vec<String> {
        self.ops
            .hooks
            .iter()
            .find(|(s, _)| s == shelf)
            .and_then(|(_, per_task)| per_task.get(idx))
            .cloned()
            .unwrap_or_default()
    }

    /// Brings the I/O system to now and acts on the rising edges of system inputs.
    fn follow_inputs(&mut self, host: &mut dyn Host) {
        let mut io = rapid_signals::IoState::default();
        io.exchange_shared(self.shared.io_mut());
        io.advance(self.time);
        let changes = io.system.as_ref().map(|s| s.changes()).unwrap_or(&[]);
        let start = self.ops.seen_changes.min(changes.len());
        let mut actions = Vec::new();
        for change in &changes[start..] {
            if change.old == 0.0 && change.new == 1.0 {
                let hits = self.ops.inputs.iter().filter(|i| i.id == change.id);
                actions.extend(hits.map(|i| (i.action, i.arg.clone())));
            }
        }
        self.ops.seen_changes = changes.len();
        io.exchange_shared(self.shared.io_mut());
        for (action, arg) in actions {
            self.act(host, action, arg.as_deref());
        }
    }

    /// One system input's action.
    fn act(&mut self, host: &mut dyn Host, action: SysAction, arg: Option<&str>) {
        let mode = match arg {
            Some(a) if a.eq_ignore_ascii_case("CYCLE") => StartMode::Cycle,
            _ => StartMode::Continuous,
        };
        match action {
            SysAction::Start => {
                self.start(host, mode);
            }
            SysAction::StartMain => {
                self.start_main(host);
            }
            SysAction::Stop | SysAction::SoftStop | SysAction::StopInstr => self.stop(StopKind::Stop),
            SysAction::QuickStop => self.stop(StopKind::Quick),
            SysAction::StopCycle => self.stop(StopKind::Cycle),
            SysAction::MotorOn => self.set_motors(true),
            SysAction::MotorOff => self.set_motors(false),
            SysAction::MotorOnStart => {
                self.set_motors(true);
                self.start(host, mode);
            }
            SysAction::ResetError => {
                self.ops.errors_shown.iter_mut().for_each(|e| *e = false);
                self.ops.outputs_stale = true;
            }
            SysAction::PpToMain => self.note("PP to Main by a system input is not run by `rapid run` yet".to_owned()),
            // Left out when configured (configure_system_signals).
            SysAction::ResetEstop | SysAction::NotSimulated(_) => {}
        }
    }

    /// Whether task `task`'s robot stands still now (MechUnitNotMoving).
    fn robot_still(&self, task: &crate::schedule::Task) -> bool {
        self.time >= task.loaded.vm.resources().robot().still_from()
    }

    /// Whether a robot started or stopped since the outputs were last shown.
    fn motion_changed(&self) -> bool {
        self.ops.still_shown.len() != self.tasks.len()
            || self.tasks.iter().zip(&self.ops.still_shown).any(|(t, &shown)| self.robot_still(t) != shown)
    }

    /// Sets each system output to what it shows now.
    fn show_outputs(&mut self) {
        self.ops.outputs_stale = false;
        if self.ops.watch_motion {
            self.ops.still_shown = self.tasks.iter().map(|t| self.robot_still(t)).collect();
        }
        for (idx, task) in self.tasks.iter().enumerate() {
            // Shown when the task fails; ResetError clears it.
            if matches!(task.state, State::Ended(TaskEnd::Failed(_))) && !self.ops.errors_seen[idx] {
                self.ops.errors_seen[idx] = true;
                self.ops.errors_shown[idx] = true;
            }
        }
        let running = self.ops.state() != ProgramState::Stopped && self.any_normal_running();
        let values: Vec<(u32, f64)> = self
            .ops
            .outputs
            .iter()
            .map(|o| {
                let on = match o.status {
                    SysStatus::CycleOn => running,
                    SysStatus::MotorOn | SysStatus::MotOnState => !self.ops.motors_off,
                    SysStatus::MotorOff | SysStatus::MotOffState => self.ops.motors_off,
                    SysStatus::AutoOn => self.ops.auto,
                    SysStatus::TaskExecuting => o.task.is_some_and(|i| self.executing(i)),
                    SysStatus::Error => match o.task {
                        Some(i) => self.ops.errors_shown.get(i).copied().unwrap_or(false),
                        None => self.ops.errors_shown.iter().any(|&e| e),
                    },
                    SysStatus::RunchOk => true,
                    // No emergency stop, and never in simulated mode (the Sim Mode input
                    // is not simulated).
                    SysStatus::EmStop | SysStatus::SimMode => false,
                    // Without `-Arg1`, every unit: 1 while none moves (a task that moves
                    // nothing always stands still).
                    // uncertain: RobotWare's meaning of the output without `-Arg1`.
                    SysStatus::MechUnitNotMoving => match o.task {
                        Some(i) => self.robot_still(&self.tasks[i]),
                        None => self.tasks.iter().all(|t| self.robot_still(t)),
                    },
                    // A TCP robot is always active (DeactUnit refuses it), with or without
                    // `-Arg1` (external units are refused by `unit_task`).
                    SysStatus::MechUnitActive => true,
                    // Left out when configured (configure_system_signals).
                    SysStatus::NotSimulated(_) => false,
                };
                (o.id, if on { 1.0 } else { 0.0 })
            })
            .collect();
        let time = self.time;
        if let Some(io) = self.shared.io_mut().system.as_mut() {
            for (id, value) in values {
                // The value is a digital one of a DO (checked with the configuration).
                let _ = io.set_by_system(id, value, time);
            }
        }
    }

    /// Whether task `idx` executes: it has not ended and, a NORMAL task, the program
    /// is not stopped.
    fn executing(&self, idx: usize) -> bool {
        let task = &self.tasks[idx];
        if matches!(task.state, State::Ended(_)) {
            return false;
        }
        task.spec.kind != TaskKind::Normal || self.ops.state() != ProgramState::Stopped
    }

    /// Records what an operation did; the outputs show the new state.
    fn note(&mut self, text: String) {
        self.ops.journal.push((self.time, text));
        self.ops.outputs_stale = true;
    }
}

/// The system event number of a shelf (1 POWER_ON … 7 STEP).
fn event_number(shelf: &str) -> u8 {
    rapid_config::sys::SHELVES.iter().position(|s| *s == shelf).map_or(0, |i| i as u8 + 1)
}

/// Seconds to the millisecond, trailing zeros dropped.
fn trim(x: f64) -> String {
    let text = format!("{x:.3}");
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

mod api_hooks;
mod step;
#[cfg(test)]
mod tests;
