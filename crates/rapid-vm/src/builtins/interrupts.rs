//! Interrupts (§1.11): the task's interrupt table and the instructions that order,
//! deactivate and delete interrupts — ITimer, IPers, IError, IDelete, ISleep,
//! IWatch, IDisable, IEnable. Signal interrupts (ISignalDI …) are ordered by the
//! extension that keeps the signals (rapid-signals): it sets `Source::Signal` or
//! `Source::Analog`, and hands the signal changes to the executor
//! (`TaskHooks::signal_changes`). CONNECT (compiled) gives an intnum its identity and trap;
//! the executor (`exec/interrupts.rs`) notices events and runs the traps.
//!
//! An intnum holds its interrupt's number (0: none). Events of an interrupt that is
//! asleep are dropped; while interrupts are disabled they queue, first in first out, at
//! most `MAX_QUEUED` (manual §1.11: interrupts are queued while disabled or while a trap
//! runs).
//!
//! Safe interrupts (§1.11 安全中断, ordered with `\SingleSafe`): while the program is
//! stopped ([`InterruptState::program_stopped`]) the queue keeps only safe interrupts
//! and only their events are queued; the others are dropped. When the program starts
//! again the queued safe interrupts run first, in the order they came.

use super::{native, present, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

type Res = Result<Option<Value>, RapidError>;

/// Interrupts waiting for their trap.
// uncertain: the controller's queue length is not public; 100 as the issue states.
pub const MAX_QUEUED: usize = 100;

/// What makes an interrupt fire.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// ITimer: every `period` seconds, the next at `next`; `single` fires once.
    Timer { period: f64, next: f64, single: bool },
    /// ISignalDI/ISignalDO: when signal `id` changes to `value` (2: any change).
    Signal { id: u32, value: f64, single: bool },
    /// ISignalAI/ISignalAO: when a new value of analog signal `id` meets `trigger`.
    Analog { id: u32, trigger: AnalogTrigger, single: bool },
    /// IPers: when the persistent at `place` gets a value other than `last`.
    Pers { place: crate::value::Place, last: Value, single: bool },
    /// IError: an event-log entry of `domain` (0: any), number `id` (any when `None`)
    /// and `kind` (0 any, 1 state, 2 warning, 3 error).
    Error { domain: u32, id: Option<u32>, kind: u32 },
    /// IRMQMessage: a message of this data type (name as declared, array sizes)
    /// arrived in the task's queue. The one piece of RMQ the core keeps: interrupts
    /// are the language's mechanism, and a trap is ordered by the data type; the
    /// queues and the hand-over of a message are the controller's RMQ binding's
    /// (`TaskHooks::deliver`).
    Rmq { datatype: String, dims: [u32; 3] },
}

/// The condition of an analog signal interrupt, kept by the extension that keeps the
/// signals: each new value of the signal is a sample, which fires the interrupt or not.
pub trait SampleTrigger: std::fmt::Debug {
    /// Whether the new value `value` fires the interrupt (the trigger may keep it as
    /// its new reference).
    fn sample(&mut self, value: f64) -> bool;
    fn clone_box(&self) -> Box<dyn SampleTrigger>;
}

/// An analog interrupt's condition ([`SampleTrigger`]), as interrupt data.
#[derive(Debug)]
pub struct AnalogTrigger(pub Box<dyn SampleTrigger>);

impl AnalogTrigger {
    pub fn sample(&mut self, value: f64) -> bool {
        self.0.sample(value)
    }
}

impl Clone for AnalogTrigger {
    fn clone(&self) -> Self {
        AnalogTrigger(self.0.clone_box())
    }
}

impl PartialEq for AnalogTrigger {
    /// Two triggers are equal when they show the same condition and reference.
    fn eq(&self, other: &Self) -> bool {
        format!("{:?}", self.0) == format!("{:?}", other.0)
    }
}

/// One connected interrupt.
#[derive(Debug, Clone, PartialEq)]
pub struct Interrupt {
    /// The TRAP routine (a routine index).
    pub trap: u32,
    pub source: Option<Source>,
    /// ISleep: events are dropped until IWatch.
    pub asleep: bool,
    /// Ordered with `\SingleSafe`: its events are kept across a program stop.
    pub safe: bool,
}

/// A program stop under way (the controller's stop, not the Stop instruction).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProgramStop {
    /// The controller time of the stop.
    pub since: f64,
    /// Whether the stop stopped the robot on its path (it is moved on at the start).
    pub paused_robot: bool,
}

/// The task's interrupts.
#[derive(Debug, Default)]
pub struct InterruptState {
    /// By number - 1.
    pub table: Vec<Option<Interrupt>>,
    /// Fired, waiting for their trap to run.
    pub queue: std::collections::VecDeque<u32>,
    /// IDisable.
    pub disabled: bool,
    /// How much of the I/O change log signal interrupts have seen.
    pub seen_changes: usize,
    /// The number of the first event-log entry error interrupts have not seen.
    pub next_event: u64,
    /// For each queued interrupt fired by an event-log entry: that entry's number.
    pub events: Vec<(u32, u64)>,
    /// The event of the trap that runs now (GetTrapData).
    pub trap_event: Option<u64>,
    /// How much of the controller-wide log (other tasks' entries) IError has seen.
    pub next_foreign: usize,
    /// Interrupts to fire at a controller time (TriggInt): (time, number).
    pub scheduled: Vec<(f64, u32)>,
    /// One-off interrupts (Move*Sync's procedures), freed when they start.
    pub once: Vec<u32>,
    /// The program is stopped: only safe interrupts queue.
    pub stop: Option<ProgramStop>,
}

/// A trapdata handle or an event number with this bit set names an entry of the
/// controller-wide log (another task's), by its index there.
pub const FOREIGN_EVENT: u64 = 1 << 31;

impl InterruptState {
    /// Whether anything can fire (the executor then watches every instruction).
    pub fn active(&self) -> bool {
        !self.queue.is_empty() || !self.scheduled.is_empty() || self.table.iter().flatten().any(|i| i.source.is_some())
    }

    /// The interrupts IError ordered for an event-log entry like `event` (its domain,
    /// number and type), by number.
    pub(crate) fn error_interrupts_for<'a>(
        &'a self,
        event: &'a crate::events::Event,
    ) -> impl Iterator<Item = u32> + 'a {
        self.table.iter().enumerate().filter_map(move |(idx, slot)| {
            let Some(Source::Error { domain, id, kind }) = slot.as_ref().and_then(|i| i.source.as_ref()) else {
                return None;
            };
            let domain_ok = *domain == 0 || *domain == event.domain;
            let id_ok = id.is_none_or(|id| id == event.number);
            let kind_ok = *kind == 0 || *kind == event_type(event.kind);
            (domain_ok && id_ok && kind_ok).then_some(idx as u32 + 1)
        })
    }

    /// Fires interrupt `number` at `time` (a trigger on the robot's path).
    pub fn schedule(&mut self, time: f64, number: u32) {
        self.scheduled.push((time, number));
    }

    /// When the next timer (or scheduled interrupt) is due.
    pub fn next_timer(&self) -> Option<f64> {
        self.table
            .iter()
            .flatten()
            .filter_map(|i| match i.source {
                Some(Source::Timer { next, .. }) => Some(next),
                _ => None,
            })
            .chain(self.scheduled.iter().map(|&(t, _)| t))
            .min_by(f64::total_cmp)
    }

    /// Whether any interrupt watches signals.
    pub fn watches_signals(&self) -> bool {
        self.table.iter().flatten().any(|i| matches!(i.source, Some(Source::Signal { .. } | Source::Analog { .. })))
    }

    /// A one-off interrupt running procedure `routine` when it fires (Move*Sync): its
    /// number. Its slot is freed when the procedure starts.
    pub fn once(&mut self, routine: u32) -> u32 {
        let number = self.connect(routine);
        self.once.push(number);
        number
    }

    /// Frees a one-off interrupt's slot once its procedure has started.
    pub fn started(&mut self, number: u32) {
        if let Some(at) = self.once.iter().position(|&n| n == number) {
            self.once.remove(at);
            if let Some(slot) = self.table.get_mut(number as usize - 1) {
                *slot = None;
            }
        }
    }

    /// A new interrupt for `trap`; its number.
    pub fn connect(&mut self, trap: u32) -> u32 {
        self.table.push(Some(Interrupt { trap, source: None, asleep: false, safe: false }));
        self.table.len() as u32
    }

    pub fn get_mut(&mut self, number: u32) -> Option<&mut Interrupt> {
        self.table.get_mut((number as usize).checked_sub(1)?)?.as_mut()
    }

    /// An event of interrupt `number`: queued unless it sleeps (or the queue is full),
    /// or the program is stopped and the interrupt is not safe (§1.11).
    pub fn fire(&mut self, number: u32) {
        let stopped = self.stop.is_some();
        let wanted = self.get_mut(number).is_some_and(|i| !i.asleep && (i.safe || !stopped));
        if wanted && self.queue.len() < MAX_QUEUED {
            self.queue.push_back(number);
        }
    }

    /// Whether interrupt `number` was ordered with `\SingleSafe`.
    pub fn is_safe(&self, number: u32) -> bool {
        let slot = (number as usize).checked_sub(1).and_then(|i| self.table.get(i));
        slot.and_then(Option::as_ref).is_some_and(|i| i.safe)
    }

    /// The program stops at `time` (§1.11): the queue keeps only its safe interrupts,
    /// and until [`InterruptState::program_started`] only safe ones queue.
    pub fn program_stopped(&mut self, time: f64, paused_robot: bool) {
        let queue = std::mem::take(&mut self.queue);
        self.queue = queue.into_iter().filter(|&n| self.is_safe(n)).collect();
        let queue = &self.queue;
        self.events.retain(|(n, _)| queue.contains(n));
        self.stop = Some(ProgramStop { since: time, paused_robot });
    }

    /// The timers that came due while the program stood, up to `now`: each period that
    /// ended is an event (a safe timer, single by `\SingleSafe`, queues its one event;
    /// the others are dropped), and a periodic timer goes on from its next period
    /// after `now`.
    // uncertain: the manual does not say whether a timer goes on counting while the
    // program is stopped; we take it that it does (its events are what a safe interrupt
    // keeps).
    pub fn catch_up_timers(&mut self, now: f64) {
        let mut fired = Vec::new();
        for (idx, slot) in self.table.iter_mut().enumerate() {
            let Some(interrupt) = slot else { continue };
            let Some(Source::Timer { period, next, single }) = &mut interrupt.source else { continue };
            if *next > now {
                continue;
            }
            let periods = ((now - *next) / *period).floor() + 1.0;
            let events = if *single { 1 } else { periods.min(MAX_QUEUED as f64) as usize };
            fired.extend(std::iter::repeat_n(idx as u32 + 1, events));
            if *single {
                interrupt.source = None;
            } else {
                *next += periods * *period;
            }
        }
        for number in fired {
            self.fire(number);
        }
    }

    /// The program starts again: the stop ends (what it was, for the caller). The safe
    /// interrupts queued meanwhile are first in the queue, in the order they came.
    pub fn program_started(&mut self) -> Option<ProgramStop> {
        self.stop.take()
    }

    /// PP to Main: interrupts are deleted (§1.2.2 start-up table).
    pub fn clear(&mut self) {
        *self = InterruptState::default();
    }
}

/// When the next interrupt may fire (a timer, or any signal change while signal
/// interrupts are ordered); `None` when none can.
pub fn next_due(ctx: &mut Ctx<'_>) -> Option<f64> {
    let timer = ctx.resources.interrupts.next_timer();
    let signal = if ctx.resources.interrupts.watches_signals() { super::wait::next_event(ctx) } else { None };
    match (timer, signal) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// The connected interrupt an intnum argument names; ERR_UNKINO when none.
pub fn interrupt_number(ctx: &mut Ctx<'_>, arg: &Value) -> Result<u32, RapidError> {
    let number = ctx.num(arg)?;
    let n = number as u32;
    if number.fract() != 0.0 || number < 1.0 || ctx.resources.interrupts.get_mut(n).is_none() {
        return Err(ctx.error(Err::UnknownInterrupt, "the intnum is not connected to a trap (CONNECT)"));
    }
    Ok(n)
}

super::signature::layout! {
    static ITIMER: TimerArgs = "ITimer" {
        single: "Single", single_safe: "SingleSafe", time: "Time", interrupt: "Interrupt",
    }
    static IPERS: PersArgs = "IPers" {
        single: "Single", single_safe: "SingleSafe", name: "Name", interrupt: "Interrupt",
    }
    static IERROR: ErrorArgs = "IError" {
        domain: "ErrorDomain", id: "ErrorId", kind: "ErrorType", interrupt: "Interrupt",
    }
    static READ_ERR_DATA: ReadErrArgs = "ReadErrData" {
        trap_event: "TrapEvent", domain: "ErrorDomain", id: "ErrorId", kind: "ErrorType", title: "Title",
        str1: "Str1", str5: "Str5",
    }
}

/// `ITimer [\Single] | [\SingleSafe] Time Interrupt`.
fn itimer(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ITIMER;
    let single = present(args.get(at.single)) || present(args.get(at.single_safe));
    let period = ctx.num(&args[at.time])?;
    // uncertain: the manual's lower limit for Time is not public; 0.1 s (the controller's
    // timer resolution) is our floor, below it ERR_ARGVALERR.
    if !period.is_finite() || period < 0.1 {
        return Err(ctx.error(Err::ArgValue, format!("ITimer time {period} s is below 0.1 s")));
    }
    let n = interrupt_number(ctx, &args[at.interrupt])?;
    let next = ctx.time + period;
    if let Some(interrupt) = ctx.resources.interrupts.get_mut(n) {
        interrupt.source = Some(super::interrupts::Source::Timer { period, next, single });
        interrupt.safe = present(args.get(at.single_safe));
    }
    Ok(None)
}

/// `IPers [\Single] | [\SingleSafe] Name Interrupt`: every change of a persistent's
/// value.
fn ipers(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *IPERS;
    let single = present(args.get(at.single)) || present(args.get(at.single_safe));
    let Value::Ref(place) = &args[at.name] else { return Err(ctx.error(Err::ArgValue, "IPers needs a persistent")) };
    let place = (**place).clone();
    let last = ctx.value(&args[at.name])?;
    let n = interrupt_number(ctx, &args[at.interrupt])?;
    if let Some(interrupt) = ctx.resources.interrupts.get_mut(n) {
        interrupt.source = Some(Source::Pers { place, last, single });
        interrupt.safe = present(args.get(at.single_safe));
    }
    Ok(None)
}

/// `IError ErrorDomain [\ErrorId] ErrorType Interrupt`: an interrupt for event-log
/// entries (manual §1.11, §1.12): errors, warnings or state changes of a domain.
fn ierror(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *IERROR;
    let domain = ctx.num(&args[at.domain])? as u32;
    let id = ctx.opt_num(args.get(at.id))?.map(|n| n as u32);
    let kind = ctx.num(&args[at.kind])? as u32;
    let n = interrupt_number(ctx, &args[at.interrupt])?;
    // Only entries from now on count (this task's and the other tasks').
    let next = ctx.events.entries().last().map_or(0, |e| e.seq + 1);
    let foreign = ctx.resources.tasks.shared.events.len();
    let interrupts = &mut ctx.resources.interrupts;
    interrupts.next_event = interrupts.next_event.max(next);
    interrupts.next_foreign = interrupts.next_foreign.max(foreign);
    if let Some(interrupt) = interrupts.get_mut(n) {
        interrupt.source = Some(Source::Error { domain, id, kind });
    }
    Ok(None)
}

/// `GetTrapData TrapEvent`: in a trap started by IError, what started it.
// uncertain: outside such a trap the manual names no error; ERR_ARGVALERR.
fn get_trap_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let Some(seq) = ctx.resources.interrupts.trap_event else {
        return Err(ctx.error(Err::ArgValue, "GetTrapData outside a trap started by IError"));
    };
    let Value::Opaque(shell) = ctx.value(&args[0])? else {
        return Err(ctx.error(Err::ArgValue, "TrapEvent must be trapdata"));
    };
    let data = crate::value::Opaque { ty: shell.ty, state: crate::value::OpaqueState::Handle(seq as u32) };
    ctx.store(&args[0], Value::Opaque(Box::new(data)))?;
    Ok(None)
}

/// `ReadErrData TrapEvent ErrorDomain ErrorId ErrorType [\Title] [\Str1] … [\Str5]`.
fn read_err_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *READ_ERR_DATA;
    let seq = match ctx.value(&args[at.trap_event])? {
        Value::Opaque(o) => match o.state {
            crate::value::OpaqueState::Handle(seq) => Some(u64::from(seq)),
            _ => None,
        },
        _ => None,
    };
    let event = seq.and_then(|seq| {
        if seq & FOREIGN_EVENT != 0 {
            let index = (seq & !FOREIGN_EVENT) as usize;
            return ctx.resources.tasks.shared.events.get(index).map(|(_, e)| e.clone());
        }
        ctx.events.entries().iter().find(|e| e.seq == seq).cloned()
    });
    let Some(event) = event else {
        return Err(ctx.error(Err::ArgValue, "TrapEvent holds no event (GetTrapData first)"));
    };
    ctx.store(&args[at.domain], Value::Num(event.domain as f32))?;
    ctx.store(&args[at.id], Value::Num(event.number as f32))?;
    ctx.store(&args[at.kind], Value::Num(event_type(event.kind) as f32))?;
    if present(args.get(at.title)) {
        ctx.store(&args[at.title], Value::Str(limit(&event.title).into()))?;
    }
    // \Str1 … \Str5 follow one another: a system error's detail, then the lines.
    let strings = event.details.iter().chain(&event.lines).map(Some).chain(std::iter::repeat(None));
    for (k, line) in (at.str1..=at.str5).zip(strings) {
        if present(args.get(k)) {
            ctx.store(&args[k], Value::Str(limit(line.map_or("", |l| l.as_str())).into()))?;
        }
    }
    Ok(None)
}

/// A message text as a RAPID string (at most 80 characters).
fn limit(text: &str) -> String {
    text.chars().take(crate::value::MAX_STRING_CHARS).collect()
}

/// errtype of an event: TYPE_STATE 1 (information), TYPE_WARN 2, TYPE_ERR 3.
pub(crate) fn event_type(kind: crate::events::EventKind) -> u32 {
    match kind {
        crate::events::EventKind::Info => 1,
        crate::events::EventKind::Warning => 2,
        crate::events::EventKind::Error => 3,
    }
}

/// `IDelete Interrupt`: the interrupt is gone; the intnum may be connected again.
fn idelete(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let number = ctx.num(&args[0])?;
    let n = number as u32;
    if let Some(slot) = (n as usize).checked_sub(1).and_then(|i| ctx.resources.interrupts.table.get_mut(i)) {
        *slot = None;
    }
    ctx.resources.interrupts.queue.retain(|&q| q != n);
    ctx.store(&args[0], Value::Num(0.0))?;
    Ok(None)
}

fn isleep(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    set_asleep(ctx, args, true)
}

fn iwatch(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    set_asleep(ctx, args, false)
}

fn set_asleep(ctx: &mut Ctx<'_>, args: &[Value], asleep: bool) -> Res {
    let n = interrupt_number(ctx, &args[0])?;
    if let Some(interrupt) = ctx.resources.interrupts.get_mut(n) {
        interrupt.asleep = asleep;
    }
    Ok(None)
}

fn idisable(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    ctx.resources.interrupts.disabled = true;
    Ok(None)
}

fn ienable(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    ctx.resources.interrupts.disabled = false;
    Ok(None)
}

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("ITimer", itimer),
        native("IPers", ipers),
        native("IError", ierror),
        native("GetTrapData", get_trap_data),
        native("ReadErrData", read_err_data),
        native("IDelete", idelete),
        native("ISleep", isleep),
        native("IWatch", iwatch),
        native("IDisable", idisable),
        native("IEnable", ienable),
    ],
};

#[cfg(test)]
mod tests {
    use super::{InterruptState, Source};

    /// Interrupts 1 (plain) and 2 (safe), both timers of 1 s due at 1.
    fn two_timers() -> InterruptState {
        let mut state = InterruptState::default();
        for safe in [false, true] {
            let n = state.connect(0);
            let interrupt = state.get_mut(n).expect("connected");
            interrupt.source = Some(Source::Timer { period: 1.0, next: 1.0, single: safe });
            interrupt.safe = safe;
        }
        state
    }

    #[test]
    fn a_stop_keeps_only_safe_interrupts_queued_and_queues_only_safe_events() {
        let mut state = two_timers();
        state.fire(1);
        state.fire(2);
        state.fire(1);
        state.program_stopped(0.5, false);
        assert_eq!(state.queue, [2]);
        state.fire(1);
        state.fire(2);
        assert_eq!(state.queue, [2, 2]);
        assert_eq!(state.program_started().map(|s| s.since), Some(0.5));
        state.fire(1);
        assert_eq!(state.queue, [2, 2, 1]);
    }

    #[test]
    fn timers_due_while_stopped_fire_once_and_go_on_from_their_next_period() {
        let mut state = two_timers();
        state.program_stopped(0.5, false);
        state.catch_up_timers(3.5);
        // The plain periodic timer's events (1, 2, 3) are dropped; it is next due at 4.
        // The safe single timer queued its one event and is spent.
        assert_eq!(state.queue, [2]);
        assert_eq!(state.next_timer(), Some(4.0));
        assert!(state.get_mut(2).is_some_and(|i| i.source.is_none()));
    }
}
