//! Execution control for front ends: start (from the program pointer or from main),
//! stop, PP to Main and to a routine, steps (into, over, out, backward), breakpoints,
//! running under a clock policy, and each task's program pointer and call stack.

use std::time::{Duration, Instant};

use rapid_vm::builtins::controller::RunMode;
use rapid_vm::Host;

use super::debug::{BreakpointHit, Location, StepKind};
use super::{ApiError, Session};
use crate::run::{Bound, ClockPolicy, RunBounds, WallClock};
use crate::schedule::State;
use crate::task::TaskKind;
use crate::{ProgramState, StartMode, StopKind, SystemExit};

/// Statements one [`Session::run_until`] round runs before it looks at its condition.
const ROUND: u64 = 1000;
/// Instructions a stop may take to reach each task's instruction boundary.
const MAX_SETTLE_ROUNDS: u32 = 100_000;
/// The longest sleep a paced clock asks for at once.
const MAX_SLEEP: f64 = 60.0;

/// Where a start begins.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StartFrom {
    /// Where each task's program pointer stands.
    Pointer,
    /// PP to Main first (data initialised again, persistents kept), then start.
    Main,
}

/// What [`Session::run`] did.
#[derive(Debug, Clone, PartialEq)]
pub enum RunOutcome {
    /// Work was done; call again.
    Running,
    /// A paced clock waits for the wall clock: call again after this long.
    Sleep(Duration),
    /// The program stopped at a breakpoint (reported once; it stands stopped).
    Breakpoint(BreakpointHit),
    /// The program stands stopped (a stop, a step done, a Stop instruction).
    Stopped,
    /// Every NORMAL task has ended.
    Ended,
}

/// A condition [`Session::run_until`] runs to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Until {
    /// The program stands stopped (or has ended).
    Stopped,
    /// The controller clock reaches this time (seconds); a stopped program stands
    /// meanwhile, the clock moving on.
    Time(f64),
    /// This many more statements have run (all tasks together).
    Steps(u64),
}

/// A task as a front end lists it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TaskView {
    pub name: String,
    /// `NORMAL`, `STATIC` or `SEMISTATIC`.
    pub kind: &'static str,
    /// `active` or how it ended (as in the stream).
    pub state: String,
    /// It waits (a wait instruction, a move, a prompt) rather than computes.
    pub waiting: bool,
    pub motion: bool,
}

/// One routine of a task's call stack.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StackFrame {
    /// Where the frame stands (for a caller: its call).
    pub at: Location,
    /// `ERROR`, `UNDO` or `BACKWARD` when the frame runs that handler.
    pub handler: Option<&'static str>,
    /// A TRAP routine an interrupt started.
    pub trap: bool,
}

impl Session {
    /// The tasks, in configuration order.
    pub fn tasks(&self) -> Vec<TaskView> {
        self.controller
            .tasks
            .iter()
            .map(|t| TaskView {
                name: t.spec.name.clone(),
                kind: match t.spec.kind {
                    TaskKind::Normal => "NORMAL",
                    TaskKind::Static => "STATIC",
                    TaskKind::SemiStatic => "SEMISTATIC",
                },
                state: super::task_state_name(&t.state),
                waiting: matches!(t.state, State::Waiting { .. }),
                motion: t.spec.motion,
            })
            .collect()
    }

    /// The clock policy from now on.
    pub fn set_clock(&mut self, policy: ClockPolicy) {
        self.clock = policy;
        self.wall = Anchor::default();
    }

    /// Runs the program to its end or a bound with the front end's own pendant
    /// `host` and `clock` (which may block): the one run loop
    /// ([`crate::Controller::run_until`]) under the session's clock policy. `rapid
    /// run` is this call.
    pub fn run_to_end(&mut self, host: &mut dyn Host, clock: &mut dyn WallClock, bounds: RunBounds) -> Option<Bound> {
        let bound = self.controller.run_until(host, clock, self.clock, bounds);
        self.gather();
        bound
    }

    pub(super) fn must_be_stopped(&self) -> Result<(), ApiError> {
        match self.controller.program_state() {
            ProgramState::Stopped => Ok(()),
            other => {
                Err(ApiError::WrongState(format!("the program is not stopped ({})", super::program_state_name(other))))
            }
        }
    }

    /// A NORMAL task by name.
    fn normal_task(&self, task: &str) -> Result<usize, ApiError> {
        let idx = self.task_index(task)?;
        if self.controller.tasks[idx].spec.kind != TaskKind::Normal {
            return Err(ApiError::Refused(format!(
                "task {task} is no NORMAL task: the program's operations do not reach it"
            )));
        }
        Ok(idx)
    }

    /// Starts the stopped program (every NORMAL task). A breakpoint on the statement
    /// a task stands on is passed.
    // uncertain: the first start after boot runs the RESTART event routines (a start
    // from where the PP stands, `Controller::start`), not START: the controller runs
    // START for a start after PP to Main, which `StartFrom::Main` is.
    pub fn start(&mut self, from: StartFrom) -> Result<(), ApiError> {
        self.must_be_stopped()?;
        let started = match from {
            StartFrom::Pointer => {
                self.pass_all();
                self.controller.start(&mut self.pendant, StartMode::Continuous)
            }
            StartFrom::Main => {
                let started = self.controller.start_main(&mut self.pendant);
                self.pass_all();
                started
            }
        };
        if !started {
            return Err(ApiError::WrongState("the motors are off".into()));
        }
        self.wall = Anchor::default();
        self.gather();
        Ok(())
    }

    fn pass_all(&mut self) {
        for idx in 0..self.controller.tasks.len() {
            self.controller.pass_current(idx);
        }
    }

    /// Stops the running program: `Stop` and `Quick` at each NORMAL task's next
    /// instruction (done when this returns), `Cycle` at the end of the cycle. A step
    /// under way (a long step over) ends at its task's next statement instead.
    pub fn stop(&mut self, kind: StopKind) -> Result<(), ApiError> {
        if matches!(self.controller.program_state(), ProgramState::Stepping { .. }) {
            self.controller.watch.end_step();
            return Ok(());
        }
        if self.controller.program_state() != ProgramState::Running {
            return Err(ApiError::WrongState("the program is not running".into()));
        }
        self.controller.stop(kind);
        if kind != StopKind::Cycle {
            self.settle();
        }
        self.gather();
        Ok(())
    }

    /// Lets a stop under way reach every task's instruction boundary.
    pub(super) fn settle(&mut self) {
        for _ in 0..MAX_SETTLE_ROUNDS {
            if !matches!(self.controller.program_state(), ProgramState::Stopping { .. }) {
                return;
            }
            self.controller.run(&mut self.pendant, 1);
        }
    }

    /// PP to Main in every NORMAL task of the stopped program: UNDO handlers run,
    /// data gets its initial values again (persistents keep theirs).
    pub fn pp_to_main(&mut self) -> Result<(), ApiError> {
        self.must_be_stopped()?;
        let names: Vec<String> = self
            .controller
            .tasks
            .iter()
            .filter(|t| t.spec.kind == TaskKind::Normal)
            .map(|t| t.spec.name.clone())
            .collect();
        for name in names {
            self.pendant.drop_task(&name);
        }
        let outcome = self.controller.pp_to_main_all(&mut self.pendant).map_err(ApiError::Failed);
        self.gather();
        outcome
    }

    /// PP to procedure `routine` (without parameters) in NORMAL task `task` of the
    /// stopped program: its running routines' UNDO handlers run, data keeps its values.
    pub fn pp_to_routine(&mut self, task: &str, routine: &str) -> Result<(), ApiError> {
        self.must_be_stopped()?;
        let idx = self.normal_task(task)?;
        self.pendant.drop_task(&self.controller.tasks[idx].spec.name.clone());
        let moved = self.controller.pp_to_routine_in(&mut self.pendant, idx, routine).map_err(ApiError::Failed);
        self.gather();
        match moved? {
            true => Ok(()),
            false => Err(ApiError::NotFound(format!("task {task} has no procedure `{routine}` without parameters"))),
        }
    }

    /// Starts a step of NORMAL task `task` of the stopped program; [`Session::run`]
    /// carries it out, and the program stands stopped again when it is done (a move
    /// step, [`StepKind::Motion`], when a motion instruction has run).
    pub fn step(&mut self, task: &str, kind: StepKind) -> Result<(), ApiError> {
        self.must_be_stopped()?;
        let idx = self.normal_task(task)?;
        let vm = &self.controller.tasks[idx].loaded.vm;
        if matches!(self.controller.tasks[idx].state, State::Ended(_)) || vm.depth() == 0 {
            return Err(ApiError::WrongState(format!("task {task} has ended: PP to Main first")));
        }
        if kind == StepKind::Out && vm.depth() <= 1 {
            return Err(ApiError::Refused(format!(
                "task {task} stands in its entry routine: there is no caller to step out to"
            )));
        }
        self.controller.pass_current(idx);
        let mode = if kind == StepKind::Motion { RunMode::StepMove } else { RunMode::InstrFwd };
        if !self.controller.step_forward_as(&mut self.pendant, idx, mode) {
            return Err(ApiError::WrongState("the controller refused the step (motors off?)".into()));
        }
        self.controller.watch_step(idx, kind);
        self.gather();
        Ok(())
    }

    /// One step backward of NORMAL task `task` of the stopped program (§1.21): the
    /// program pointer moves back over the previous statement of its routine, a call
    /// running the procedure's BACKWARD handler. Refused where RAPID refuses it (inside
    /// IF/FOR/WHILE/TEST, at a routine's start, a procedure without BACKWARD handler);
    /// refused as not supported yet over a motion instruction (the robot would have
    /// to move back along its path).
    pub fn step_backward(&mut self, task: &str) -> Result<rapid_vm::BackStep, ApiError> {
        self.must_be_stopped()?;
        let idx = self.normal_task(task)?;
        if let Some(word) = self.previous_statement_word(idx) {
            if is_motion_instruction(&word) {
                return Err(ApiError::Unsupported(format!(
                    "stepping backward over the motion instruction {word} (the robot moving back along its path)"
                )));
            }
        }
        self.controller.set_run_mode(RunMode::InstrBwd);
        let outcome = self.controller.with_task(idx, &mut self.pendant, |vm, host| vm.step_backward(host));
        self.gather();
        outcome.map_err(|refusal| ApiError::Refused(format!("no step backward in task {task}: {refusal:?}")))
    }

    /// The first word of the statement before task `idx`'s program pointer in its
    /// routine (what a step backward would undo).
    fn previous_statement_word(&self, idx: usize) -> Option<String> {
        let vm = &self.controller.tasks[idx].loaded.vm;
        let (code, pc) = vm.top_position()?;
        let prev = code.stmts.iter().filter(|s| s.depth == 0).rfind(|s| s.end <= pc)?;
        let text = &vm.program_source(code.file)?.text;
        let from = text.get(prev.span.start as usize..)?;
        Some(from.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect())
    }

    /// Sets a breakpoint on the statement starting on `line` of `file` (a path as
    /// loaded, or just the file's name) in every NORMAL task running that file;
    /// returns where it resolved. NotFound when no statement starts on that line.
    pub fn set_breakpoint(&mut self, file: &str, line: u32) -> Result<Vec<Location>, ApiError> {
        let found = self.controller.add_breakpoint(file, line);
        if found.is_empty() {
            return Err(ApiError::NotFound(format!("no statement of a NORMAL task starts on line {line} of {file}")));
        }
        Ok(found)
    }

    /// Exception breakpoints: the program stops when a NORMAL task's error is about to
    /// be taken by an ERROR handler (`raised`), or reaches none and is about to stop
    /// the task (`uncaught`); [`RunOutcome::Breakpoint`] then carries the error.
    pub fn set_error_breaks(&mut self, raised: bool, uncaught: bool) {
        self.controller.watch_errors(raised, uncaught);
    }

    /// Removes the breakpoint at `line` of `file`; false when there was none.
    pub fn clear_breakpoint(&mut self, file: &str, line: u32) -> bool {
        self.controller.remove_breakpoint(file, line)
    }

    /// The breakpoints set, as (file, line).
    pub fn breakpoints(&self) -> Vec<(String, u32)> {
        self.controller.watch.points.iter().map(|p| (p.file.clone(), p.line)).collect()
    }

    /// Where task `task`'s program pointer stands (None: its program has ended).
    pub fn program_pointer(&self, task: &str) -> Result<Option<Location>, ApiError> {
        let idx = self.task_index(task)?;
        Ok(self.controller.location_of(idx))
    }

    /// Task `task`'s call stack, innermost routine first (as debuggers list it).
    pub fn call_stack(&self, task: &str) -> Result<Vec<StackFrame>, ApiError> {
        let idx = self.task_index(task)?;
        let frames = self.controller.tasks[idx].loaded.vm.call_stack();
        Ok(frames
            .iter()
            .rev()
            .map(|f| StackFrame {
                at: self.controller.location(idx, &f.routine, f.file, f.span.start),
                handler: match f.handler {
                    1 => Some("BACKWARD"),
                    2 => Some("ERROR"),
                    3 => Some("UNDO"),
                    _ => None,
                },
                trap: f.trap,
            })
            .collect())
    }

    /// The parameters and routine data of frame `frame` of task `task`'s call stack
    /// (0: the innermost, as [`Session::call_stack`] lists them), as (name, RAPID
    /// literal text); an optional parameter not passed shows as `<not present>`, data
    /// of a non-value type as `<no literal>`.
    pub fn frame_locals(&self, task: &str, frame: usize) -> Result<Vec<(String, String)>, ApiError> {
        let idx = self.task_index(task)?;
        let vm = &self.controller.tasks[idx].loaded.vm;
        let locals = vm
            .depth()
            .checked_sub(frame + 1)
            .and_then(|at| vm.frame_locals(at))
            .ok_or_else(|| ApiError::NotFound(format!("task {task} has no frame {frame}")))?;
        Ok(locals
            .into_iter()
            .map(|(name, value)| {
                let text = match value {
                    rapid_vm::value::Value::Absent => "<not present>".to_owned(),
                    rapid_vm::value::Value::SwitchOn => "<present>".to_owned(),
                    other => rapid_vm::builtins::value_literal(&other).unwrap_or_else(|| "<no literal>".to_owned()),
                };
                (name, text)
            })
            .collect())
    }

    /// Runs at most `budget` statements (all tasks together), moving the clock as
    /// the policy says while every task waits.
    pub fn run(&mut self, budget: u64) -> RunOutcome {
        self.run_limited(budget, f64::INFINITY)
    }

    /// Runs until `until` holds, at most `max_steps` statements; returns early for a
    /// breakpoint, the program's end or a stop, and when a paced clock must sleep.
    pub fn run_until(&mut self, until: Until, max_steps: u64) -> RunOutcome {
        let start = self.controller.steps;
        let limit = match until {
            Until::Time(t) => t,
            _ => f64::INFINITY,
        };
        loop {
            let done = self.controller.steps - start;
            let reached = match until {
                Until::Stopped => self.controller.program_state() == ProgramState::Stopped,
                Until::Time(t) => self.controller.time >= t,
                Until::Steps(n) => done >= n,
            };
            if reached {
                return if until == Until::Stopped { RunOutcome::Stopped } else { RunOutcome::Running };
            }
            if done >= max_steps {
                return RunOutcome::Running;
            }
            let budget = match until {
                Until::Steps(n) => (n - done).min(ROUND),
                _ => ROUND,
            }
            .min(max_steps - done);
            match self.run_limited(budget, limit) {
                RunOutcome::Running => {}
                RunOutcome::Stopped if until != Until::Stopped && limit.is_finite() => {
                    // A stopped program stands while the clock moves on.
                    let time = self.controller.time;
                    self.controller.advance((limit - time).max(0.0));
                }
                other => return other,
            }
        }
    }

    /// [`Session::run`] with the clock moving no further than `limit`: one turn of
    /// the run loop, the clock moved by [`crate::Controller::move_clock`].
    fn run_limited(&mut self, budget: u64, limit: f64) -> RunOutcome {
        let exit = self.controller.run(&mut self.pendant, budget);
        let mut outcome = match exit {
            SystemExit::Budget | SystemExit::Wait(_) => {
                // While a dialog waits for the operator, a person is part of the loop:
                // the clock is the wall clock (a virtual clock would jump over the hour
                // a dialog without \MaxTime polls in), as a run's clock is while a task
                // talks to a socket.
                let operator = self.pendant.pending().next().is_some();
                let policy = match self.clock {
                    ClockPolicy::Virtual if operator => ClockPolicy::Paced { rate: 1.0 },
                    policy => policy,
                };
                self.controller.move_clock(exit, &mut self.wall, policy, limit);
                match self.wall.sleep.take() {
                    Some(sleep) => RunOutcome::Sleep(sleep),
                    None => RunOutcome::Running,
                }
            }
            SystemExit::Ended => RunOutcome::Ended,
            SystemExit::Stopped => RunOutcome::Stopped,
        };
        if let Some(hit) = self.controller.watch.hit.take() {
            self.settle();
            let change =
                super::Change::Breakpoint { task: hit.at.task.clone(), file: hit.file.clone(), line: hit.line };
            self.stream.push(change);
            outcome = RunOutcome::Breakpoint(hit);
        }
        self.gather();
        outcome
    }
}

/// The session's wall clock: it never blocks. A paced wait the wall clock has not
/// reached yet moves the controller clock as far as the wall clock has come and says
/// how long the caller should sleep.
#[derive(Debug, Default)]
pub(super) struct Anchor {
    /// Wall-clock instant and controller time tied together.
    tied: Option<(Instant, f64)>,
    /// How long the caller should sleep before the next turn.
    sleep: Option<Duration>,
}

impl WallClock for Anchor {
    fn wait(&mut self, rate: Option<f64>, from: f64, to: f64, limit: f64) -> f64 {
        let Some(rate) = rate else {
            self.tied = None;
            return to;
        };
        let (wall0, clock0) = *self.tied.get_or_insert((Instant::now(), from));
        let wall_clock = clock0 + wall0.elapsed().as_secs_f64() * rate;
        if from == to {
            // Computing: the clock catches up with the wall clock.
            return to.max(wall_clock.min(limit));
        }
        if wall_clock >= to {
            return to;
        }
        self.sleep = Some(Duration::from_secs_f64(((to - wall_clock) / rate).min(MAX_SLEEP)));
        wall_clock.max(from)
    }

    fn interrupted(&self) -> bool {
        false
    }
}

/// Whether an instruction moves the robot (a step backward over it would move it
/// back along its path).
pub(super) fn is_motion_instruction(word: &str) -> bool {
    let word = word.to_ascii_lowercase();
    ["move", "search", "trigg", "arc", "capture", "cirpath"].iter().any(|p| word.starts_with(p))
        || ["egm", "spot", "paint"].iter().any(|p| word.starts_with(p))
}
