//! The I/O system proper: current values, program orders and hardware writes at a virtual
//! time, the pending pulse ends and delayed changes, cross-connection propagation and the
//! change log.

use std::collections::{BTreeSet, HashMap};
use std::sync::Arc;

use crate::cross::CrossNet;
use crate::def::{check_signal, ConfigError, CrossConnection, SignalDef, SignalKind};
use crate::units::{DeviceDef, UnitError, Units};
use crate::value::{check_time, check_value, to_physical, IoError};

/// A signal's dense index: the order of the definitions given to [`IoSystem::new`].
pub type SignalId = u32;

/// At most this many signals pulse at the same time (manual §2.10).
pub const MAX_PULSING: usize = rapid_limits::PULSES;
/// At most this many signals have a delayed change pending at the same time (manual §2.10).
pub const MAX_DELAYED: usize = rapid_limits::DELAYED_ORDERS;
/// PulseDO without `\PLength` pulses for 0.2 s.
pub const DEFAULT_PULSE_LENGTH: f64 = 0.2;

/// What made a signal change; kept in the log for `--io-log`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cause {
    /// A program order carried out at once (Set, Reset, SetDO, SetAO, SetGO, InvertDO, the
    /// start of a pulse).
    Order,
    /// A `\SDelay` order that came due.
    Delayed,
    /// The end of a pulse.
    PulseEnd,
    /// The hardware (or a stimulus) changed an input.
    Hardware,
    /// A cross-connection followed one of its actors.
    Cross,
}

/// One change of a signal's value.
#[derive(Debug, Clone, PartialEq)]
pub struct Change {
    pub time: f64,
    pub id: SignalId,
    pub signal: Arc<str>,
    pub old: f64,
    pub new: f64,
    pub cause: Cause,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum PendingKind {
    Delayed,
    /// The end of a pulse; `restore` is the value the signal returns to.
    PulseEnd,
}

/// A change ordered for later. A signal has at most one (a new order cancels the old one).
#[derive(Debug, Clone, PartialEq)]
struct Pending {
    id: SignalId,
    time: f64,
    value: f64,
    kind: PendingKind,
    /// Order of issue, so that changes due at the same instant apply in the order given.
    seq: u64,
}

/// The I/O system of one controller.
#[derive(Debug, Clone)]
pub struct IoSystem {
    defs: Vec<SignalDef>,
    names: Vec<Arc<str>>,
    ids: HashMap<String, SignalId>,
    values: Vec<f64>,
    net: CrossNet,
    pending: Vec<Pending>,
    seq: u64,
    now: f64,
    changes: Vec<Change>,
    units: Units,
}

impl IoSystem {
    /// Builds the system and puts every signal at its default value; then every
    /// cross-connection is evaluated once, upstream first, so that the start state already
    /// satisfies them. Those start values are not logged as changes.
    // uncertain: that cross-connections hold from start-up (e.g. `do5 = NOT di1` gives do5 = 1
    // at once) rather than only after the first change of an actor.
    pub fn new(defs: Vec<SignalDef>, crosses: Vec<CrossConnection>) -> Result<IoSystem, ConfigError> {
        let mut ids = HashMap::with_capacity(defs.len());
        for (index, def) in defs.iter().enumerate() {
            check_signal(index, def)?;
            // RAPID names are case-insensitive, so signals differing only in case would clash.
            let key = def.name.to_ascii_lowercase();
            if ids.insert(key, index as SignalId).is_some() {
                return Err(ConfigError::DuplicateSignal { index, name: def.name.clone() });
            }
        }
        let net = CrossNet::build(&defs, &ids, &crosses)?;
        let mut system = IoSystem {
            names: defs.iter().map(|d| Arc::from(d.name.as_str())).collect(),
            values: defs.iter().map(|d| d.default).collect(),
            defs,
            ids,
            net,
            pending: Vec::new(),
            seq: 0,
            now: 0.0,
            changes: Vec::new(),
            units: Units::default(),
        };
        let mut order: Vec<usize> = (0..system.net.crosses.len()).collect();
        order.sort_by_key(|i| system.net.crosses[*i].key);
        for index in order {
            let cross = &system.net.crosses[index];
            let value = if cross.eval(&system.values) { 1.0 } else { 0.0 };
            system.values[cross.result as usize] = value;
        }
        Ok(system)
    }

    /// Adds a virtual signal (on no device) after start-up, at its default value: a
    /// simulation aid for programs whose I/O configuration is not at hand.
    pub fn add_virtual(&mut self, def: SignalDef) -> Result<SignalId, ConfigError> {
        let index = self.defs.len();
        check_signal(index, &def)?;
        let key = def.name.to_ascii_lowercase();
        if self.ids.contains_key(&key) {
            return Err(ConfigError::DuplicateSignal { index, name: def.name.clone() });
        }
        let id = index as SignalId;
        self.ids.insert(key, id);
        self.names.push(Arc::from(def.name.as_str()));
        self.values.push(def.default);
        self.net.readers.push(Vec::new());
        self.net.is_result.push(false);
        self.defs.push(def);
        Ok(id)
    }

    /// Like [`IoSystem::new`], with the I/O devices and networks: every signal's `device`
    /// must be one of `devices`.
    pub fn with_units(
        defs: Vec<SignalDef>,
        crosses: Vec<CrossConnection>,
        devices: Vec<DeviceDef>,
        networks: Vec<String>,
    ) -> Result<IoSystem, ConfigError> {
        let signal_devices: Vec<(String, Option<String>)> =
            defs.iter().map(|d| (d.name.clone(), d.device.clone())).collect();
        let units = Units::new(devices, networks, &signal_devices).map_err(ConfigError::Units)?;
        let mut system = IoSystem::new(defs, crosses)?;
        system.units = units;
        Ok(system)
    }

    /// The devices and networks.
    pub fn units(&self) -> &Units {
        &self.units
    }

    /// IOEnable / IODisable at `t`. Disabling cancels the pending pulse ends and delayed
    /// changes of the device's signals: the controller loses contact with the device.
    // uncertain: what happens to pending orders of a disabled device is not public; the
    // signals keep their values and nothing more is carried out.
    pub fn set_device_enabled(&mut self, name: &str, enabled: bool, t: f64) -> Result<(), UnitError> {
        self.advance(t);
        self.units.set_enabled(name, enabled)?;
        if !enabled {
            for id in self.units.signals_of(name) {
                self.cancel(id);
            }
        }
        Ok(())
    }

    /// The device at `index` stops or starts answering at `t` (a stimulus): orders
    /// pending on its signals are dropped when it goes.
    pub fn set_device_connected(&mut self, index: usize, connected: bool, t: f64) {
        self.advance(t);
        let Some(name) = self.units.set_connected(index, connected).map(str::to_owned) else { return };
        if !connected {
            for id in self.units.signals_of(&name) {
                self.cancel(id);
            }
        }
    }

    /// Whether a signal can be reached now (virtual, or its device is enabled).
    pub fn is_running(&self, id: SignalId) -> bool {
        self.units.signal_running(id)
    }

    /// A program's read of a signal: its value, or [`IoError::NotRunning`] when its device
    /// is disabled.
    pub fn read(&self, id: SignalId) -> Result<f64, IoError> {
        self.check_running(id)?;
        self.value(id).ok_or(IoError::UnknownSignal(id))
    }

    fn check_running(&self, id: SignalId) -> Result<(), IoError> {
        if self.units.signal_running(id) {
            return Ok(());
        }
        let device = self.units.signal_device(id).map(|d| d.name.clone()).unwrap_or_default();
        Err(IoError::NotRunning { signal: self.names[id as usize].to_string(), device })
    }

    /// How many signals the system has; ids are `0..len()`.
    pub fn len(&self) -> usize {
        self.defs.len()
    }

    pub fn is_empty(&self) -> bool {
        self.defs.is_empty()
    }

    /// The id of a signal by name (case-insensitive, as RAPID names are).
    pub fn id(&self, name: &str) -> Option<SignalId> {
        self.ids.get(&name.to_ascii_lowercase()).copied()
    }

    /// Every signal definition, indexed by id.
    pub fn defs(&self) -> &[SignalDef] {
        &self.defs
    }

    pub fn def(&self, id: SignalId) -> Option<&SignalDef> {
        self.defs.get(id as usize)
    }

    pub fn name(&self, id: SignalId) -> Option<&str> {
        self.names.get(id as usize).map(|n| &**n)
    }

    /// The current (logical) value: 0/1, a group's integer, an analog logical value.
    pub fn value(&self, id: SignalId) -> Option<f64> {
        self.values.get(id as usize).copied()
    }

    pub fn value_by_name(&self, name: &str) -> Option<f64> {
        self.id(name).and_then(|id| self.value(id))
    }

    /// The physical value of an analog signal (its logical value for every other signal, and
    /// for an analog signal configured without a range).
    pub fn physical(&self, id: SignalId) -> Option<f64> {
        let value = self.value(id)?;
        match self.def(id)?.analog {
            Some(range) => Some(to_physical(&range, value)),
            None => Some(value),
        }
    }

    /// The virtual time the system has reached.
    pub fn now(&self) -> f64 {
        self.now
    }

    /// Whether a cross-connection writes this signal. For an input this means its physical
    /// channel is disconnected (manual §2.10).
    pub fn is_cross_result(&self, id: SignalId) -> bool {
        self.net.is_result.get(id as usize).copied().unwrap_or(false)
    }

    /// How many signals are pulsing / have a delayed change pending.
    pub fn pulsing(&self) -> usize {
        self.count(PendingKind::PulseEnd)
    }

    pub fn delayed(&self) -> usize {
        self.count(PendingKind::Delayed)
    }

    /// When the next pulse end or delayed change is due, if any.
    pub fn next_event_time(&self) -> Option<f64> {
        self.pending.iter().map(|p| p.time).min_by(f64::total_cmp)
    }

    /// Every change so far, oldest first.
    pub fn changes(&self) -> &[Change] {
        &self.changes
    }

    /// Takes the log, leaving it empty.
    pub fn drain_changes(&mut self) -> Vec<Change> {
        std::mem::take(&mut self.changes)
    }

    /// Applies every pending change due at or before `t`, in time order (ties in order of
    /// issue), each followed by its cross-connections. Time never runs backwards: an earlier
    /// `t` is taken as the time already reached.
    pub fn advance(&mut self, t: f64) {
        let t = if t.is_nan() { self.now } else { t.max(self.now) };
        while let Some(index) = self.next_due(t) {
            let due = self.pending.swap_remove(index);
            self.now = due.time;
            let cause = match due.kind {
                PendingKind::Delayed => Cause::Delayed,
                PendingKind::PulseEnd => Cause::PulseEnd,
            };
            self.change(due.id, due.value, cause);
        }
        self.now = t;
    }

    /// A program order to change an output now (Set, Reset, SetDO, SetAO, SetGO). It cancels a
    /// pulse or delayed change of the same signal not yet carried out (manual §2.10).
    pub fn set(&mut self, id: SignalId, value: f64, t: f64) -> Result<(), IoError> {
        self.advance(t);
        let value = self.check_order(id, value)?;
        self.cancel(id);
        self.change(id, value, Cause::Order);
        Ok(())
    }

    /// The controller sets one of its system outputs (SYSSIG_OUT) now: any access
    /// level (a read-only output is read-only for programs, not for the system); a
    /// pending order of the signal is cancelled as by a program order.
    pub fn set_by_system(&mut self, id: SignalId, value: f64, t: f64) -> Result<(), IoError> {
        self.advance(t);
        let def = self.def_of(id)?;
        if def.kind.is_input() {
            return Err(self.wrong_kind(id, "a system output"));
        }
        let value = check_value(def, value)?;
        if self.values.get(id as usize) == Some(&value) {
            return Ok(());
        }
        self.cancel(id);
        self.change(id, value, Cause::Order);
        Ok(())
    }

    /// SetDO/SetGO `\SDelay`: the change happens `delay` seconds after `t`; the program goes on.
    /// The value is checked now. The order replaces any earlier pending order of the signal.
    pub fn set_delayed(&mut self, id: SignalId, value: f64, t: f64, delay: f64) -> Result<(), IoError> {
        self.advance(t);
        let value = self.check_order(id, value)?;
        let kind = self.def_of(id)?.kind;
        if !matches!(kind, SignalKind::DO | SignalKind::GO) {
            return Err(self.wrong_kind(id, "a delayed write"));
        }
        let delay = check_time("delay", delay)?;
        self.check_room(id, PendingKind::Delayed)?;
        self.cancel(id);
        self.schedule(id, self.now + delay, value, PendingKind::Delayed);
        Ok(())
    }

    /// PulseDO. Without `high`, the signal is inverted for `length` seconds and then restored;
    /// with `high` it is 1 for `length` seconds (already 1: it stays 1) and then 0. `length`
    /// is `None` for the default 0.2 s. A new pulse on a signal still pulsing restarts it: the
    /// signal keeps its pulse level and returns to its value from before the first pulse,
    /// `length` seconds from now.
    // uncertain: the restart rule for a PulseDO on a signal that is pulsing already; §2.10 only
    // says the new order cancels the pending change.
    pub fn pulse(&mut self, id: SignalId, high: bool, length: Option<f64>, t: f64) -> Result<(), IoError> {
        self.advance(t);
        if self.def_of(id)?.kind != SignalKind::DO {
            return Err(self.wrong_kind(id, "a pulse"));
        }
        self.check_writable(id)?;
        let length = check_time("pulse length", length.unwrap_or(DEFAULT_PULSE_LENGTH))?;
        self.check_room(id, PendingKind::PulseEnd)?;
        let current = self.values[id as usize];
        let running = self.pending_of(id).filter(|p| p.kind == PendingKind::PulseEnd);
        let (level, restore) = match (high, running) {
            (true, _) => (1.0, 0.0),
            (false, Some(p)) => (current, p.value),
            (false, None) => (1.0 - current, current),
        };
        self.cancel(id);
        self.change(id, level, Cause::Order);
        self.schedule(id, self.now + length, restore, PendingKind::PulseEnd);
        Ok(())
    }

    /// InvertDO: the output takes the opposite value now (an order like any other).
    pub fn invert(&mut self, id: SignalId, t: f64) -> Result<(), IoError> {
        self.advance(t);
        if self.def_of(id)?.kind != SignalKind::DO {
            return Err(self.wrong_kind(id, "inverting"));
        }
        let value = 1.0 - self.values[id as usize];
        self.set(id, value, t)
    }

    /// The hardware (or a stimulus) changes an input at `t`. Returns `false`, changing nothing,
    /// when a cross-connection drives the input: its physical channel is then disconnected and
    /// the controller sees no change of it (manual §2.10).
    pub fn set_input(&mut self, id: SignalId, value: f64, t: f64) -> Result<bool, IoError> {
        self.advance(t);
        let def = self.def_of(id)?;
        if !def.kind.is_input() {
            return Err(self.wrong_kind(id, "a hardware write"));
        }
        let value = check_value(def, value)?;
        // A cross-connected input has no physical channel; a disabled device sends nothing.
        if self.is_cross_result(id) || !self.units.signal_running(id) {
            return Ok(false);
        }
        self.change(id, value, Cause::Hardware);
        Ok(true)
    }

    fn def_of(&self, id: SignalId) -> Result<&SignalDef, IoError> {
        self.defs.get(id as usize).ok_or(IoError::UnknownSignal(id))
    }

    fn wrong_kind(&self, id: SignalId, order: &'static str) -> IoError {
        match self.defs.get(id as usize) {
            Some(def) => IoError::WrongKind { signal: def.name.clone(), kind: def.kind, order },
            None => IoError::UnknownSignal(id),
        }
    }

    fn check_writable(&self, id: SignalId) -> Result<(), IoError> {
        let def = self.def_of(id)?;
        if def.kind.is_input() {
            return Err(self.wrong_kind(id, "a program write"));
        }
        if !def.access.rapid_may_write() {
            return Err(IoError::AccessDenied { signal: def.name.clone() });
        }
        self.check_running(id)
    }

    /// Checks a program order's value. SetDO takes any value other than 0 as 1 (the SetDO
    /// manual's table of specified values), so a digital order never fails on its value.
    fn check_order(&self, id: SignalId, value: f64) -> Result<f64, IoError> {
        self.check_writable(id)?;
        let def = self.def_of(id)?;
        let value = if def.kind == SignalKind::DO && value.is_finite() && value != 0.0 { 1.0 } else { value };
        check_value(def, value)
    }

    /// Refuses a new pulse or delay when the limit is reached by other signals (the signal's
    /// own pending order is about to be replaced, so it does not count).
    fn check_room(&self, id: SignalId, kind: PendingKind) -> Result<(), IoError> {
        let others = self.pending.iter().filter(|p| p.kind == kind && p.id != id).count();
        let signal = || self.names[id as usize].to_string();
        match kind {
            PendingKind::PulseEnd if others >= MAX_PULSING => Err(IoError::TooManyPulses { signal: signal() }),
            PendingKind::Delayed if others >= MAX_DELAYED => Err(IoError::TooManyDelayed { signal: signal() }),
            _ => Ok(()),
        }
    }

    fn count(&self, kind: PendingKind) -> usize {
        self.pending.iter().filter(|p| p.kind == kind).count()
    }

    fn pending_of(&self, id: SignalId) -> Option<Pending> {
        self.pending.iter().find(|p| p.id == id).cloned()
    }

    fn cancel(&mut self, id: SignalId) {
        self.pending.retain(|p| p.id != id);
    }

    fn schedule(&mut self, id: SignalId, time: f64, value: f64, kind: PendingKind) {
        self.seq += 1;
        self.pending.push(Pending { id, time, value, kind, seq: self.seq });
    }

    fn next_due(&self, t: f64) -> Option<usize> {
        self.pending
            .iter()
            .enumerate()
            .filter(|(_, p)| p.time <= t)
            .min_by(|(_, a), (_, b)| a.time.total_cmp(&b.time).then(a.seq.cmp(&b.seq)))
            .map(|(i, _)| i)
    }

    /// Sets a value; if it differs, logs it and lets the cross-connections follow.
    fn change(&mut self, id: SignalId, value: f64, cause: Cause) {
        if self.write(id, value, cause) {
            self.propagate(id);
        }
    }

    /// Stores a value and logs it; `false` when the value was already there.
    fn write(&mut self, id: SignalId, value: f64, cause: Cause) -> bool {
        let slot = &mut self.values[id as usize];
        let old = *slot;
        if old == value {
            return false;
        }
        *slot = value;
        let signal = self.names[id as usize].clone();
        self.changes.push(Change { time: self.now, id, signal, old, new: value, cause });
        true
    }

    /// Re-evaluates every cross-connection reading a changed signal, upstream connections
    /// first and each at most once, so a signal reached along two paths sees its final value
    /// once. Only connections with a changed actor are evaluated: a signal written by several
    /// connections takes the value of the one activated last (manual §2.10).
    // uncertain: "activated" is read as "an actor changed value"; writing a signal its present
    // value activates nothing.
    fn propagate(&mut self, changed: SignalId) {
        let mut queue: BTreeSet<((u32, usize), usize)> = BTreeSet::new();
        self.enqueue_readers(changed, &mut queue);
        while let Some((_, index)) = queue.pop_first() {
            let cross = &self.net.crosses[index];
            let result = cross.result;
            let value = if cross.eval(&self.values) { 1.0 } else { 0.0 };
            if self.write(result, value, Cause::Cross) {
                self.enqueue_readers(result, &mut queue);
            }
        }
    }

    fn enqueue_readers(&self, id: SignalId, queue: &mut BTreeSet<((u32, usize), usize)>) {
        for &index in &self.net.readers[id as usize] {
            queue.insert((self.net.crosses[index].key, index));
        }
    }
}
