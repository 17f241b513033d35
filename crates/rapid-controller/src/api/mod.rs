//! The controller as front ends use it (an RWS server, a debugger, a language
//! server): one [`Session`] owns a [`Controller`] and is the only way in. It boots the
//! program stopped, starts and stops it, moves program pointers, steps tasks, holds
//! breakpoints, runs the clock under a policy, reads and writes data and signals by
//! name as RAPID literal text, shows the pendant (output, prompts the front end
//! answers), and gathers what changes into a bounded stream front ends subscribe to.
//!
//! Nothing here blocks: [`Session::run`] does a bounded amount of work and says when
//! to come back (a paced clock tells the caller how long to sleep; a prompt makes
//! its task wait while the others run). Errors the front end can cause are
//! [`ApiError`]s, never panics.
//!
//! Modules: `debug` (breakpoints, steps, locations), `data` (data and signals by
//! name), `pendant` (the `Host` the tasks run with), `stream` (subscriptions),
//! `exec` (run, clock policies, start/stop, program pointers, call stacks), `panel`
//! (motors, run mode, the robots' positions, the file devices' folder), `modules`
//! (list, load, unload a task's modules, a module's text and attributes), `config`
//! (the system parameters booted with), `rmq` (messages to a
//! task's RAPID Message Queue), `inspect` (values as trees, expressions
//! evaluated in a frame).

mod config;
pub mod data;
pub mod debug;
mod exec;
mod inspect;
mod modules;
pub mod motion;
pub mod panel;
pub mod pendant;
mod rmq;
pub mod stream;

use std::fmt;

pub use crate::run::ClockPolicy;
pub use config::{ConfigDomain, ConfigInstance, ConfigType};
pub use data::{DataInfo, DataValue};
pub use debug::{BreakpointHit, ErrorHit, Location, StepKind};
pub use exec::{RunOutcome, StackFrame, StartFrom, TaskView, Until};
pub use inspect::ValueTree;
pub use modules::ModuleInfo;
pub use panel::MechUnitView;
pub use pendant::PendingPrompt;
pub use rmq::ClientMessage;
pub use stream::{Batch, Change, Subscription};

use crate::schedule::{Controller, State};
use crate::task::TaskEnd;
use crate::ProgramState;

/// Why the API refused a request.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ApiError {
    /// No such task, module, data, signal, routine, file line or prompt.
    NotFound(String),
    /// A data path that cannot be read.
    BadPath(String),
    /// Text that is no RAPID literal of the datum's type.
    BadLiteral(String),
    /// The datum may not be written (a CONST).
    ReadOnly(String),
    /// The request needs the program in another state (stopped, say).
    WrongState(String),
    /// The controller refused it (RAPID's rules, e.g. a step backward past a call
    /// without a BACKWARD handler).
    Refused(String),
    /// Not supported yet by this controller.
    Unsupported(String),
    /// A task failed while carrying it out (an UNDO handler's error, say).
    Failed(String),
}

impl fmt::Display for ApiError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ApiError::NotFound(why) => write!(f, "not found: {why}"),
            ApiError::BadPath(why) => write!(f, "bad data path: {why}"),
            ApiError::BadLiteral(why) => write!(f, "bad value: {why}"),
            ApiError::ReadOnly(why) => write!(f, "read-only: {why}"),
            ApiError::WrongState(why) => write!(f, "not now: {why}"),
            ApiError::Refused(why) => write!(f, "refused: {why}"),
            ApiError::Unsupported(why) => write!(f, "not supported yet: {why}"),
            ApiError::Failed(why) => write!(f, "failed: {why}"),
        }
    }
}

impl std::error::Error for ApiError {}

/// What the stream has reported so far, to tell what changed since.
#[derive(Debug, Default)]
struct Seen {
    program: String,
    tasks: Vec<String>,
    signals: usize,
    pers_generation: u64,
    /// By task: the sequence number of the next event-log entry.
    events: Vec<u64>,
}

/// A front end's handle on a running controller.
pub struct Session {
    controller: Controller,
    pendant: pendant::Pendant,
    stream: stream::Stream,
    clock: ClockPolicy,
    /// The wall clock a paced clock follows (never blocking).
    wall: exec::Anchor,
    seen: Seen,
}

impl Session {
    /// Boots `controller`: its program stands stopped with every NORMAL task's
    /// program pointer at its entry routine (STATIC and SEMISTATIC tasks run as soon
    /// as the session runs); the clock is virtual.
    pub fn new(mut controller: Controller) -> Session {
        controller.stand_stopped();
        Session::running(controller)
    }

    /// A session on `controller` as it stands: a front end that powered it on and
    /// started it itself (`rapid run`: power on ran the event routines) drives it from
    /// there. The clock is virtual.
    pub fn running(controller: Controller) -> Session {
        let mut session = Session {
            controller,
            pendant: pendant::Pendant::default(),
            stream: stream::Stream::default(),
            clock: ClockPolicy::Virtual,
            wall: exec::Anchor::default(),
            seen: Seen::default(),
        };
        session.mark_seen();
        session
    }

    /// The controller, the session ended (what a front end reports after the run).
    pub fn into_controller(self) -> Controller {
        self.controller
    }

    /// The controller, to read what the API does not offer.
    pub fn controller(&self) -> &Controller {
        &self.controller
    }

    /// The controller, to configure it (event routines, system signals).
    pub fn controller_mut(&mut self) -> &mut Controller {
        &mut self.controller
    }

    /// The program's state.
    pub fn program_state(&self) -> ProgramState {
        self.controller.program_state()
    }

    /// The controller clock, seconds.
    pub fn time(&self) -> f64 {
        self.controller.time
    }

    /// The index of task `name` (any letter case).
    fn task_index(&self, name: &str) -> Result<usize, ApiError> {
        self.controller
            .tasks
            .iter()
            .position(|t| t.spec.name.eq_ignore_ascii_case(name))
            .ok_or_else(|| ApiError::NotFound(format!("no task `{name}`")))
    }

    /// The pendant's screen: the newest lines written (at most 100) since the last
    /// TPErase, oldest first.
    pub fn tp_screen(&self) -> Vec<String> {
        self.pendant.screen.iter().cloned().collect()
    }

    /// The dialogs waiting for the operator.
    pub fn prompts(&self) -> Vec<PendingPrompt> {
        self.pendant.pending().cloned().collect()
    }

    /// Answers prompt `id` with `text` as the operator would (a number, a function
    /// key's number or text, a button's text); its task reads it when it next runs.
    pub fn answer(&mut self, id: u64, text: &str) -> Result<(), ApiError> {
        if !self.pendant.answer(id, text) {
            return Err(ApiError::NotFound(format!("no prompt {id} waits for an answer")));
        }
        // The waiting dialog re-checks when the shared state changes.
        self.controller.shared_mut().tasks.epoch += 1;
        self.gather();
        Ok(())
    }

    /// Every task's event log, oldest first within each task.
    pub fn event_log(&self) -> Vec<(String, rapid_vm::events::Event)> {
        let mut entries = Vec::new();
        for task in &self.controller.tasks {
            entries.extend(task.loaded.vm.event_log().iter().map(|e| (task.spec.name.clone(), e.clone())));
        }
        entries.sort_by(|a, b| a.1.time.total_cmp(&b.1.time));
        entries
    }

    /// A new subscription to the change stream, from now on.
    pub fn subscribe(&mut self) -> Subscription {
        if !self.stream.has_subscribers() {
            self.gather();
            self.mark_seen();
        }
        self.stream.subscribe()
    }

    pub fn unsubscribe(&mut self, sub: Subscription) {
        self.stream.unsubscribe(sub);
    }

    /// The changes since this subscriber's last poll, in order.
    pub fn poll(&mut self, sub: Subscription) -> Result<Batch, ApiError> {
        self.gather();
        self.stream.poll(sub).ok_or_else(|| ApiError::NotFound("no such subscription".into()))
    }

    /// Everything as it stands now counts as reported.
    fn mark_seen(&mut self) {
        let c = &self.controller;
        self.seen = Seen {
            program: program_state_name(c.program_state()),
            tasks: c.tasks.iter().map(|t| task_state_name(&t.state)).collect(),
            signals: c.io_system().map_or(0, |io| io.changes().len()),
            pers_generation: c.pers.generation,
            events: c.tasks.iter().map(|t| t.loaded.vm.event_log().last().map_or(0, |e| e.seq + 1)).collect(),
        };
    }

    /// Puts what changed since the last look into the stream (when anyone listens).
    fn gather(&mut self) {
        for change in std::mem::take(&mut self.pendant.changes) {
            self.stream.push(change);
        }
        if !self.stream.has_subscribers() {
            return;
        }
        let c = &self.controller;
        let program = program_state_name(c.program_state());
        if program != self.seen.program {
            self.stream.push(Change::Execution { state: program.clone() });
            self.seen.program = program;
        }
        for (idx, task) in c.tasks.iter().enumerate() {
            let state = task_state_name(&task.state);
            if self.seen.tasks.get(idx) != Some(&state) {
                self.stream.push(Change::Task { task: task.spec.name.clone(), state: state.clone() });
                self.seen.tasks.resize(c.tasks.len(), String::new());
                self.seen.tasks[idx] = state;
            }
        }
        if let Some(io) = c.io_system() {
            let changes = io.changes();
            for change in &changes[self.seen.signals.min(changes.len())..] {
                let (name, value, time) = (change.signal.to_string(), change.new, change.time);
                self.stream.push(Change::Signal { name, value, time });
            }
            self.seen.signals = changes.len();
        }
        let pers_changed = c.pers.generation != self.seen.pers_generation;
        let mut pers: Vec<(String, String)> = c
            .pers
            .changed_since(self.seen.pers_generation)
            .filter(|_| pers_changed)
            .map(|(name, value, _)| (name.to_owned(), rapid_vm::builtins::value_literal(value).unwrap_or_default()))
            .collect();
        pers.sort();
        for (name, value) in pers {
            self.stream.push(Change::Persistent { name, value });
        }
        self.seen.pers_generation = c.pers.generation;
        self.seen.events.resize(c.tasks.len(), 0);
        for (idx, task) in c.tasks.iter().enumerate() {
            let log = task.loaded.vm.event_log();
            let start = log.partition_point(|e| e.seq < self.seen.events[idx]);
            for e in &log[start..] {
                let kind = format!("{:?}", e.kind).to_lowercase();
                let (title, time) = (e.title.clone(), e.time);
                self.stream.push(Change::Event { task: task.spec.name.clone(), code: e.code(), kind, title, time });
            }
            if let Some(last) = log.last() {
                self.seen.events[idx] = last.seq + 1;
            }
        }
    }
}

/// The program state as the stream names it.
fn program_state_name(state: ProgramState) -> String {
    match state {
        ProgramState::Running => "Running",
        ProgramState::Stopping { .. } => "Stopping",
        ProgramState::Stopped => "Stopped",
        ProgramState::Stepping { .. } => "Stepping",
    }
    .to_owned()
}

/// A task's state as the stream names it: `active` until it ends (whether it
/// computes or waits changes every few statements; the program's state says whether
/// it is stopped), then how it ended.
fn task_state_name(state: &State) -> String {
    match state {
        State::Ready | State::Waiting { .. } => "active".to_owned(),
        State::Ended(TaskEnd::Done) => "ended".to_owned(),
        State::Ended(TaskEnd::Stopped) => "ended: stopped".to_owned(),
        State::Ended(TaskEnd::CycleEnded) => "ended: cycle".to_owned(),
        State::Ended(TaskEnd::Halted) => "ended: halted".to_owned(),
        State::Ended(TaskEnd::Failed(unhandled)) => format!("ended: {}", unhandled.error),
    }
}
