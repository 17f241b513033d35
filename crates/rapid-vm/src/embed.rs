//! What an embedder adds to the language (issue 19: the interpreter core knows no
//! controller). An [`Extension`] brings built-in families, the per-task state they
//! keep, and the [`TaskHooks`] the core loop calls at the few points where it must
//! ask the embedder's side (a move under way, the program stopping, interrupts the
//! path triggers). A set of built-ins is assembled from the core families and the
//! extensions (`builtins::Builtins::new`) and handed to the load; every task loaded
//! with it gets the extensions' state in its [`Extensions`] slot.
//!
//! The model is wasmtime's `Store<T>` with `WasiView` and boa's runtime extensions:
//! the engine holds state it does not know the type of, and the host's functions find
//! their own by type.
//!
//! What this module must not know: any extension's types (the robot's, I/O's).

use std::any::{Any, TypeId};

use crate::builtins::{Ctx, Family, Resources};
use crate::error::RapidError;
use crate::exec::storage::Storage;
use crate::value::Value;

/// An embedder's addition to the language.
pub struct Extension {
    /// A short name, for messages.
    pub name: &'static str,
    /// The built-in families it registers (after the core's: a name the core already
    /// registers stays the core's, and the catalogue tests refuse the second).
    pub families: &'static [&'static Family],
    /// What the core loop asks it, if anything.
    pub hooks: Option<&'static dyn TaskHooks>,
    /// Puts its per-task state into a new task's resources (`Resources::extensions`).
    pub init: Option<fn(&mut Resources)>,
}

/// The points where the interpreter's loop asks the embedder's side. Every method has
/// a default that answers as if the extension had nothing under way, so an extension
/// implements only those it needs. The hooks hold no state of their own: what they
/// look at is in the task's resources (an extension's in [`Extensions`]).
pub trait TaskHooks: Sync {
    /// The time until which the program owes a wait it was cut out of (a move's wait
    /// a trap interrupted): while there is one, the loop runs one instruction at a
    /// time and resumes the wait as soon as it may.
    fn program_hold(&self, _resources: &Resources) -> Option<f64> {
        None
    }

    /// The owed wait is over (its time has come).
    fn release_hold(&self, _resources: &mut Resources) {}

    /// Whether the embedder's side stands held by the program (a robot StopMove
    /// stopped): a program stop leaves it held, a start does not release it.
    fn held(&self, _resources: &Resources) -> bool {
        false
    }

    /// Before the loop looks for interrupts due by `now`: actions decided along the
    /// path (trigger I/O) happen, interrupts the path orders are queued.
    fn poll(&self, _resources: &mut Resources, _storage: &Storage, _now: f64) {}

    /// The program stopped itself (Stop) at `now`.
    fn program_stopped(&self, _resources: &mut Resources, _storage: &mut Storage, _now: f64) {}

    /// A built-in call has returned at `now`: hand over the events noticed since the
    /// last look (as [`TaskHooks::take_events`]), publish what other tasks read of this
    /// one, and answer whether the program now owes a wait
    /// ([`TaskHooks::program_hold`] is some). One call per built-in call: the fast loop
    /// runs through here after every call, so an extension answers from its state in
    /// one look.
    fn after_builtin(&self, resources: &mut Resources, now: f64, events: &mut Vec<PendingEvent>) -> bool {
        events.extend(self.take_events(resources, now));
        self.program_hold(resources).is_some()
    }

    /// Events the extension noticed since it was last asked (`now` is the task's
    /// time), for the task's event log; the core places each at its statement and
    /// routine.
    fn take_events(&self, _resources: &mut Resources, _now: f64) -> Vec<PendingEvent> {
        Vec::new()
    }

    /// The task was given its outside world (`Vm::set_world`; the file devices took
    /// its disk): an extension that reaches the network takes it out of `net` (the
    /// first to take it has it) and keeps the clock its waits run on.
    fn world_given(
        &self,
        _resources: &mut Resources,
        _net: &mut Option<Box<dyn crate::world::Network>>,
        _clock: &std::rc::Rc<dyn crate::world::Clock>,
    ) {
    }

    /// A built-in is about to look at a path on the file devices (`Ctx::resolve_path`):
    /// what the task wrote but still holds in write buffers reaches the disk first.
    fn flush_files(&self, _resources: &mut Resources) {}
    /// Whether the extension's side stands still before a stop-point instruction goes
    /// on (WaitTime, WaitSyncTask `\InPos`): `false` after setting `ctx.wait` and
    /// `StopKind::Repeat` while it still moves.
    fn stands_still(&self, _ctx: &mut Ctx<'_>) -> Result<bool, RapidError> {
        Ok(true)
    }

    /// ExitCycle ends the cycle: what the extension has under way stops and is
    /// dropped (the robot's paths).
    fn exit_cycle(&self, _ctx: &mut Ctx<'_>) -> Result<(), RapidError> {
        Ok(())
    }

    /// The program was loaded: the extension learns the predefined data and types it
    /// works with (`find_data` gives a predefined data object's global index by name).
    fn loaded(&self, _resources: &mut Resources, _program: &rapid_sema::Program) {}

    /// The program's data was (re)initialised (PP to Main): data the extension
    /// connects from the start (the configuration's signals) is connected again.
    fn data_initialised(&self, _resources: &mut Resources, _storage: &mut Storage) {}

    /// The next time something the extension simulates changes by itself (a signal
    /// order scheduled, a stimulus line): waits and interrupts look again then.
    fn next_event(&self, _resources: &mut Resources) -> Option<f64> {
        None
    }

    /// The value of signal data (`data`, a handle the extension gave) read in an
    /// expression at `time`: `None` when the extension keeps no signals; `Err(None)`
    /// when the data is connected to no signal (ERR_NO_ALIASIO_DEF), `Err(Some(why))`
    /// when the signal cannot be read now (ERR_NORUNUNIT).
    fn read_signal(
        &self,
        _resources: &mut Resources,
        _time: f64,
        _data: &Value,
    ) -> Option<Result<f64, Option<String>>> {
        None
    }

    /// The signal signal data (an argument, `\UIActiveSignal` of a wait's box) is
    /// connected to, checked to be reachable now; `None` when the extension keeps no
    /// signals.
    fn signal_of(&self, _ctx: &mut Ctx<'_>, _arg: &Value) -> Option<Result<u32, RapidError>> {
        None
    }

    /// Sets signal `id` (a digital output) to `value` now; `None` when the extension
    /// keeps no signals.
    fn set_signal(&self, _ctx: &mut Ctx<'_>, _id: u32, _value: f64) -> Option<Result<(), RapidError>> {
        None
    }

    /// Swaps the part of the task's state every task of a controller shares with the
    /// controller's (`Vm::exchange_shared`): `shared` holds the extensions' shared
    /// state, one value per type, as [`Extensions`] holds a task's. (State an extension
    /// keeps whole in `Shared::lent` needs no hook: the core swaps that map whole.)
    fn exchange_shared(&self, _resources: &mut Resources, _shared: &mut Extensions) {}

    /// Interrupts for what reached the task from other tasks or from outside (the
    /// messages of its RAPID Message Queue): fired at the start of a run (what came
    /// while the task did not run) and where the loop looks for interrupts, whenever
    /// the shared change count (`builtins::tasks::SharedTasks::epoch`) moved since the
    /// last call: an extension that puts something into a task's reach bumps it.
    fn deliver(&self, _resources: &mut Resources) {}

    /// For signal interrupts (`Source::Signal`, `Source::Analog`): brings the signals
    /// up to `now` and hands the changes logged from entry `from` of the extension's
    /// change log as (signal, new value), in the order they happened; answers the
    /// log's length (where the next look starts), `None` when the extension keeps no
    /// signals.
    fn signal_changes(
        &self,
        _resources: &mut Resources,
        _now: f64,
        _from: usize,
        _changes: &mut Vec<(u32, f64)>,
    ) -> Option<usize> {
        None
    }
}

/// An event an extension logs, not placed yet: the core fills in the place from
/// `at` (file index and span of the statement it concerns).
pub struct PendingEvent {
    pub event: crate::events::Event,
    pub at: Option<(usize, rapid_syntax::Span)>,
}

/// State an extension keeps per task. `close_all` runs where the core closes what the
/// task holds open (end of program, PP to Main: files, sockets, waits under way).
pub trait TaskState: Any {
    fn close_all(&mut self) {}

    /// [`TaskState::close_all`] with the shared state lent to the task at hand
    /// (`Resources::lent`): for state that must also leave what the tasks share
    /// (a task in synchronized movement leaves the list of such tasks).
    fn close_all_lent(&mut self, _lent: &mut Extensions) {
        self.close_all();
    }
}

/// The extensions' per-task state, one value per type.
///
/// A small type map rather than a generic parameter (`Vm<T>`, `Ctx<T>`): built-ins are
/// plain function pointers in static family tables, which a type parameter would turn
/// into generic tables and monomorphise the whole interpreter per embedder; a
/// controller installs several extensions that know nothing of each other (the robot,
/// I/O, multitasking), each finding its own state by type. The map holds a handful of
/// entries, each beside its `TypeId`: a lookup is a scan comparing ids (no call
/// through the trait object until the one that matches), made by the built-ins that
/// need the state and by the hooks that swap the shared state in and out before and
/// after every statement of a controller's task.
#[derive(Default)]
pub struct Extensions {
    entries: Vec<(TypeId, Box<dyn TaskState>)>,
}

impl Extensions {
    /// Where the state of type `T` is, if an extension put one in.
    #[inline]
    fn position<T: TaskState>(&self) -> Option<usize> {
        let id = TypeId::of::<T>();
        self.entries.iter().position(|(entry, _)| *entry == id)
    }

    /// Puts `state` in, replacing a value of its type.
    pub fn insert<T: TaskState>(&mut self, state: T) {
        match self.position::<T>() {
            Some(at) => self.entries[at].1 = Box::new(state),
            None => self.entries.push((TypeId::of::<T>(), Box::new(state))),
        }
    }

    /// The state of type `T`, if an extension put one in.
    #[inline]
    pub fn get<T: TaskState>(&self) -> Option<&T> {
        let at = self.position::<T>()?;
        (&*self.entries[at].1 as &dyn Any).downcast_ref::<T>()
    }

    /// The state of type `T` to change, if an extension put one in.
    #[inline]
    pub fn get_mut<T: TaskState>(&mut self) -> Option<&mut T> {
        let at = self.position::<T>()?;
        (&mut *self.entries[at].1 as &mut dyn Any).downcast_mut::<T>()
    }

    /// The state of type `T` to change, put in at its default first if there was none.
    #[inline]
    pub fn get_or_default<T: TaskState + Default>(&mut self) -> &mut T {
        let at = match self.position::<T>() {
            Some(at) => at,
            None => {
                self.entries.push((TypeId::of::<T>(), Box::<T>::default()));
                self.entries.len() - 1
            }
        };
        (&mut *self.entries[at].1 as &mut dyn Any).downcast_mut::<T>().expect("the entry at `at` is a T")
    }

    /// Whether an extension put in state of type `T`.
    pub fn contains<T: TaskState>(&self) -> bool {
        self.position::<T>().is_some()
    }

    /// Closes every entry (`TaskState::close_all_lent`), `lent` being the shared
    /// state lent to the task.
    pub(crate) fn close_all(&mut self, lent: &mut Extensions) {
        for (_, entry) in &mut self.entries {
            entry.close_all_lent(lent);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Extensions, TaskState};

    #[derive(Debug, PartialEq)]
    struct Counter(u32);
    impl TaskState for Counter {
        fn close_all(&mut self) {
            self.0 = 0;
        }
    }

    #[derive(Debug, PartialEq)]
    struct Label(&'static str);
    impl TaskState for Label {}

    #[test]
    fn each_type_finds_its_own_value() {
        let mut slot = Extensions::default();
        assert!(slot.get::<Counter>().is_none());
        slot.insert(Counter(3));
        slot.insert(Label("a"));
        assert_eq!(slot.get::<Counter>(), Some(&Counter(3)));
        assert_eq!(slot.get::<Label>(), Some(&Label("a")));
        if let Some(counter) = slot.get_mut::<Counter>() {
            counter.0 += 1;
        }
        assert_eq!(slot.get::<Counter>(), Some(&Counter(4)));
        slot.insert(Counter(9));
        assert_eq!(slot.get::<Counter>(), Some(&Counter(9)), "a second insert replaces");
    }

    #[test]
    fn closing_reaches_every_state() {
        let mut slot = Extensions::default();
        slot.insert(Counter(5));
        slot.close_all(&mut Extensions::default());
        assert_eq!(slot.get::<Counter>(), Some(&Counter(0)));
    }
}
