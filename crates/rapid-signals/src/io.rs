//! I/O signals (§1.9) on the task's I/O system (`crates/rapid-io`, an [`IoState`] in
//! the task's extension slot, reached through [`IoAccess`]), and the hooks the
//! interpreter's loop asks ([`IoHooks`]): AliasIO, AliasIOReset, Set, Reset, SetDO, SetAO, SetGO, InvertDO,
//! PulseDO, TestDI, ValidIO, GetSignalOrigin, GetGroupSignalInfo, and reading signals in
//! expressions.
//!
//! Signal data holds `OpaqueState::Handle(id)` once connected (the I/O configuration for
//! its own signals; AliasIO, which also sets `ALIAS_BIT`) and nothing before: using it
//! then raises ERR_NO_ALIASIO_DEF (manual §1.9). A signal on a disabled I/O device
//! cannot be read or written: ERR_NORUNUNIT (§1.9), and ValidIO is FALSE. Every access
//! first brings the I/O system up to the controller's time, so delayed and pulsed orders
//! take effect when they are due.

use rapid_io::{IoSystem, SignalKind};
use rapid_sema::types::TypeId;

use rapid_vm::ext::{
    native, present, Ctx, Err, Extensions, Family, Opaque, OpaqueState, RapidError, Resources, Shared, Storage,
    TaskHooks, TaskState, Value,
};

type Res = Result<Option<Value>, RapidError>;

/// The I/O system of a task and the RAPID types of its signal kinds.
#[derive(Default)]
pub struct IoState {
    pub system: Option<IoSystem>,
    /// signaldi … signalgo as this program numbers them (set at load).
    pub kinds: Vec<(TypeId, SignalKind)>,
    /// The signals of the I/O configuration as program data: (global, name).
    pub configured: Vec<(u32, String)>,
    /// Input changes from outside (a stimulus script): (time, signal, value), in time
    /// order, not yet applied.
    pub stimulus: std::collections::VecDeque<(f64, u32, f64)>,
    /// Stimulus reactions: when a signal changes to a value, an input follows.
    pub reactions: Vec<Reaction>,
    /// Outputs the robot's path sets at a time (triggers, Move*DO): (time, signal,
    /// value), in time order.
    pub path_orders: std::collections::VecDeque<(f64, u32, f64)>,
    /// How many entries of the change log the reactions have seen.
    seen_changes: usize,
    /// `--virtual-io`: AliasIO makes a virtual signal of a name the configuration
    /// lacks (also one computed at run time) instead of raising ERR_ALIASIO_DEF.
    pub virtual_io: bool,
}

/// The part of the I/O state every task of a controller shares: the signals, what the
/// stimulus still has to apply and the reactions to it.
#[derive(Default)]
pub struct SharedIo {
    pub system: Option<IoSystem>,
    pub stimulus: std::collections::VecDeque<(f64, u32, f64)>,
    pub reactions: Vec<Reaction>,
    pub path_orders: std::collections::VecDeque<(f64, u32, f64)>,
    seen_changes: usize,
}

impl SharedIo {
    /// How many signal changes the system has logged (a task waiting on a signal
    /// looks again when this grows).
    pub fn change_count(&self) -> usize {
        self.system.as_ref().map_or(0, |s| s.changes().len())
    }
}

/// A task without I/O reads this (no system, no signal kinds).
static NO_IO: IoState = IoState {
    system: None,
    kinds: Vec::new(),
    configured: Vec::new(),
    stimulus: std::collections::VecDeque::new(),
    reactions: Vec::new(),
    path_orders: std::collections::VecDeque::new(),
    seen_changes: 0,
    virtual_io: false,
};

/// A controller without I/O shares this.
static NO_SHARED_IO: SharedIo = SharedIo {
    system: None,
    stimulus: std::collections::VecDeque::new(),
    reactions: Vec::new(),
    path_orders: std::collections::VecDeque::new(),
    seen_changes: 0,
};

impl TaskState for IoState {}

impl TaskState for SharedIo {}

/// The controller's shared I/O (in `Shared::extensions`).
pub trait SharedIoAccess {
    /// The shared I/O (an empty one when there is none yet).
    fn io(&self) -> &SharedIo;
    /// The shared I/O to change (put in at its default first).
    fn io_mut(&mut self) -> &mut SharedIo;
}

impl SharedIoAccess for Shared {
    fn io(&self) -> &SharedIo {
        self.extensions.get::<SharedIo>().unwrap_or(&NO_SHARED_IO)
    }

    fn io_mut(&mut self) -> &mut SharedIo {
        self.extensions.get_or_default::<SharedIo>()
    }
}

/// The task's I/O state in its extension slot (`Resources::extensions`).
pub trait IoAccess {
    /// The task's I/O state (an empty one when it has none yet).
    fn io(&self) -> &IoState;
    /// The task's I/O state to change (put in at its default first).
    fn io_mut(&mut self) -> &mut IoState;
}

impl IoAccess for Resources {
    fn io(&self) -> &IoState {
        self.extensions.get::<IoState>().unwrap_or(&NO_IO)
    }

    fn io_mut(&mut self) -> &mut IoState {
        self.extensions.get_or_default::<IoState>()
    }
}

impl IoState {
    /// An output the robot's path sets at `time` (kept in time order).
    pub fn order_on_path(&mut self, time: f64, signal: u32, value: f64) {
        let at = self.path_orders.partition_point(|&(t, _, _)| t <= time);
        self.path_orders.insert(at, (time, signal, value));
    }

    /// Swaps the shared part with the controller's (`TaskHooks::exchange_shared`, each
    /// time the controller hands the task in or out).
    pub fn exchange_shared(&mut self, shared: &mut SharedIo) {
        std::mem::swap(&mut self.system, &mut shared.system);
        std::mem::swap(&mut self.stimulus, &mut shared.stimulus);
        std::mem::swap(&mut self.reactions, &mut shared.reactions);
        std::mem::swap(&mut self.path_orders, &mut shared.path_orders);
        std::mem::swap(&mut self.seen_changes, &mut shared.seen_changes);
    }
}

/// What the interpreter's loop asks of the I/O (`rapid_vm::ext::TaskHooks`): signals
/// read in expressions, the changes signal interrupts look at, the next scheduled
/// change (waits and interrupts look again then), the configuration's signals
/// connected at load and after PP to Main.
pub struct IoHooks;

/// The I/O's hooks (the set of built-ins asks them).
pub static HOOKS: IoHooks = IoHooks;

impl TaskHooks for IoHooks {
    fn loaded(&self, resources: &mut Resources, program: &rapid_sema::Program) {
        let io = resources.io_mut();
        io.kinds = signal_kinds(program);
        io.configured = program
            .datas
            .iter()
            .enumerate()
            .filter(|(_, data)| data.origin == rapid_sema::symbols::DeclOrigin::CONFIGURED)
            .map(|(idx, data)| (idx as u32, data.display.clone()))
            .collect();
    }

    fn data_initialised(&self, resources: &mut Resources, storage: &mut Storage) {
        connect_configured(resources, storage);
    }

    fn next_event(&self, resources: &mut Resources) -> Option<f64> {
        resources.extensions.get_mut::<IoState>()?.next_event_time()
    }

    fn read_signal(&self, resources: &mut Resources, time: f64, data: &Value) -> Option<Result<f64, Option<String>>> {
        Some(read_signal(resources, time, data))
    }

    fn signal_of(&self, ctx: &mut Ctx<'_>, arg: &Value) -> Option<Result<u32, RapidError>> {
        Some(signal(ctx, arg))
    }

    fn set_signal(&self, ctx: &mut Ctx<'_>, id: u32, value: f64) -> Option<Result<(), RapidError>> {
        Some(order(ctx, |io, t| io.set(id, value, t)).map(|_| ()))
    }

    fn exchange_shared(&self, resources: &mut Resources, shared: &mut Extensions) {
        resources.io_mut().exchange_shared(shared.get_or_default::<SharedIo>());
    }

    fn signal_changes(
        &self,
        resources: &mut Resources,
        now: f64,
        from: usize,
        changes: &mut Vec<(u32, f64)>,
    ) -> Option<usize> {
        let io = resources.io_mut();
        io.advance(now);
        let log = io.system.as_ref().map(|io| io.changes()).unwrap_or(&[]);
        changes.extend(log.get(from..).unwrap_or(&[]).iter().map(|change| (change.id, change.new)));
        Some(log.len())
    }
}

/// The program's types for the six signal kinds (AliasIO checks kinds by them).
fn signal_kinds(prog: &rapid_sema::Program) -> Vec<(TypeId, SignalKind)> {
    use SignalKind as K;
    [K::DI, K::DO, K::AI, K::AO, K::GI, K::GO]
        .into_iter()
        .filter_map(|kind| prog.types.find(kind.rapid_type()).map(|ty| (ty, kind)))
        .collect()
}

/// Configured signals are connected from the start, also after PP to Main
/// re-initialises the data.
pub fn connect_configured(resources: &Resources, storage: &mut Storage) {
    for (global, value) in resources.io().configured_values() {
        if let Some(slot) = storage.globals.get_mut(global) {
            *slot = value;
        }
    }
}

/// `when WATCH = VALUE after DELAY set TARGET SET`: every time `watch` changes to
/// `value`, input `target` becomes `set` `delay` seconds later.
#[derive(Debug, Clone, PartialEq)]
pub struct Reaction {
    pub watch: u32,
    pub value: f64,
    pub delay: f64,
    pub target: u32,
    pub set: f64,
}

/// Changes one instant may cause through reactions before the stimulus is taken to
/// loop (two reactions undoing each other with no delay).
const MAX_REACTIONS_PER_ADVANCE: usize = 100_000;

impl IoState {
    /// Brings the I/O system up to time `t`, one change at a time in time order:
    /// stimulus lines, scheduled orders, and the reactions they trigger.
    pub fn advance(&mut self, t: f64) {
        let Some(system) = self.system.as_mut() else { return };
        for _ in 0..MAX_REACTIONS_PER_ADVANCE {
            react(system, &self.reactions, &mut self.seen_changes, &mut self.stimulus);
            // Outputs the robot's path sets (triggers, Move*DO, world zones) at their time:
            // the motion system's own orders, which no program order cancels, whatever the
            // signal's access level (the program's instruction was checked when given).
            let path = self.path_orders.front().map(|&(at, _, _)| at).filter(|&at| at <= t);
            let earliest_other = [self.stimulus.front().map(|&(at, _, _)| at), system.next_event_time()]
                .into_iter()
                .flatten()
                .fold(f64::INFINITY, f64::min);
            if let Some(at) = path.filter(|&at| at <= earliest_other) {
                system.advance(at);
                if let Some((at, id, value)) = self.path_orders.pop_front() {
                    let _ = system.set_by_system(id, value, at);
                }
                continue;
            }
            let stimulus = self.stimulus.front().map(|&(at, _, _)| at).filter(|&at| at <= t);
            let scheduled = system.next_event_time().filter(|&at| at <= t);
            match (stimulus, scheduled) {
                (Some(at), order) if order.is_none_or(|o| at <= o) => {
                    system.advance(at);
                    if let Some((at, id, value)) = self.stimulus.pop_front() {
                        if id & rapid_io::DEVICE_EVENT != 0 {
                            system.set_device_connected((id & !rapid_io::DEVICE_EVENT) as usize, value != 0.0, at);
                            continue;
                        }
                        // A stimulus sets inputs, and outputs any client may write
                        // (`-Access "All"`, as an RWS client does; checked when it is
                        // read); an input a cross-connection drives ignores it, as its
                        // physical channel is off.
                        let is_input = system.def(id).is_some_and(|d| d.kind.is_input());
                        if is_input {
                            let _ = system.set_input(id, value, at);
                        } else {
                            let _ = system.set_by_system(id, value, at);
                        }
                    }
                }
                (_, Some(at)) => system.advance(at),
                _ => break,
            }
        }
        system.advance(t);
        react(system, &self.reactions, &mut self.seen_changes, &mut self.stimulus);
    }

    /// When the next signal change is due (a stimulus, a reaction or a scheduled order).
    pub fn next_event_time(&mut self) -> Option<f64> {
        let system = self.system.as_mut()?;
        react(system, &self.reactions, &mut self.seen_changes, &mut self.stimulus);
        let scheduled = system.next_event_time();
        let stimulus = self.stimulus.front().map(|&(at, _, _)| at);
        let path = self.path_orders.front().map(|&(at, _, _)| at);
        let scheduled = [scheduled, path].into_iter().flatten().min_by(f64::total_cmp);
        match (scheduled, stimulus) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// The value each configured signal's data holds: connected to its signal.
    pub fn configured_values(&self) -> Vec<(u32, Value)> {
        let Some(system) = &self.system else { return Vec::new() };
        self.configured
            .iter()
            .filter_map(|(global, name)| {
                let id = system.id(name)?;
                let kind = system.def(id)?.kind;
                let ty = self.kinds.iter().find(|(_, k)| *k == kind)?.0;
                Some((*global, Value::Opaque(Box::new(Opaque { ty, state: OpaqueState::Handle(id) }))))
            })
            .collect()
    }
}

/// Schedules the reactions to the changes logged since the last look, keeping the
/// stimulus in time order (equal times in the order they arose).
fn react(
    system: &IoSystem,
    reactions: &[Reaction],
    seen: &mut usize,
    stimulus: &mut std::collections::VecDeque<(f64, u32, f64)>,
) {
    let changes = system.changes();
    for change in changes.get(*seen..).unwrap_or(&[]) {
        for r in reactions.iter().filter(|r| r.watch == change.id && r.value == change.new) {
            let at = change.time + r.delay;
            let place = stimulus.partition_point(|&(t, _, _)| t <= at);
            stimulus.insert(place, (at, r.target, r.set));
        }
    }
    *seen = changes.len();
}

/// AliasIO marks the handle it stores with this bit, so GetSignalOrigin can tell a
/// connection made by AliasIO (SIGORIG_ALIAS) from a configured signal (SIGORIG_CFG).
const ALIAS_BIT: u32 = 1 << 31;

/// The signal signal data is connected to, and whether AliasIO connected it; `None` when
/// it is not connected.
fn handle_of(data: &Value) -> Option<(u32, bool)> {
    let Value::Opaque(opaque) = data else { return None };
    let OpaqueState::Handle(handle) = opaque.state else { return None };
    Some((handle & !ALIAS_BIT, handle & ALIAS_BIT != 0))
}

/// The value of signal data in an expression. `Err(None)`: not connected
/// (ERR_NO_ALIASIO_DEF); `Err(Some(message))`: its I/O device is disabled
/// (ERR_NORUNUNIT, manual §1.9).
pub fn read_signal(resources: &mut Resources, time: f64, data: &Value) -> Result<f64, Option<String>> {
    let (id, _) = handle_of(data).ok_or(None)?;
    resources.io_mut().advance(time);
    let system = resources.io().system.as_ref().ok_or(None)?;
    system.read(id).map_err(|fault| Some(fault.to_string()))
}

/// The signal id signal data (an argument) is connected to, checked to be reachable now:
/// ERR_NO_ALIASIO_DEF when not connected, ERR_NORUNUNIT when its device is disabled.
pub fn signal(ctx: &mut Ctx<'_>, arg: &Value) -> Result<u32, RapidError> {
    let id = connected(ctx, arg)?;
    let fault = ctx.resources.io().system.as_ref().and_then(|io| io.read(id).err());
    match fault {
        Some(fault) => Err(io_error(ctx, &fault)),
        None => Ok(id),
    }
}

/// The signal id signal data (an argument) is connected to, whatever its device's state;
/// ERR_NO_ALIASIO_DEF when not connected.
pub(crate) fn connected(ctx: &mut Ctx<'_>, arg: &Value) -> Result<u32, RapidError> {
    let data = ctx.value(arg)?;
    let Some((id, _)) = handle_of(&data) else {
        return Err(ctx.error(Err::NoAliasIoDef, "the signal variable is not connected to an I/O signal (AliasIO)"));
    };
    ctx.resources.io_mut().advance(ctx.time);
    Ok(id)
}

/// Runs an order on the I/O system and turns its failure into the RAPID error.
pub fn order(ctx: &mut Ctx<'_>, run: impl FnOnce(&mut IoSystem, f64) -> Result<(), rapid_io::IoError>) -> Res {
    let time = ctx.time;
    let Some(system) = ctx.resources.io_mut().system.as_mut() else {
        return Err(ctx.error(Err::NoAliasIoDef, "this task has no I/O system"));
    };
    match run(system, time) {
        Ok(()) => Ok(None),
        Err(fault) => Err(io_error(ctx, &fault)),
    }
}

pub fn io_error(ctx: &Ctx<'_>, fault: &rapid_io::IoError) -> RapidError {
    let named = fault.rapid_error().and_then(|name| Err::ALL.iter().copied().find(|e| e.name() == name));
    match named {
        Some(err) => ctx.error(err, fault.to_string()),
        // §2.10's limits (10 pulses, 20 delayed orders) have no recoverable error: the
        // controller stops the program with an event-log message.
        None => RapidError::fatal(fault.to_string()),
    }
}

/// `Set Signal`: a digital output to 1.
fn set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let id = signal(ctx, &args[0])?;
    order(ctx, |io, t| io.set(id, 1.0, t))
}

/// `Reset Signal`: a digital output to 0.
fn reset(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let id = signal(ctx, &args[0])?;
    order(ctx, |io, t| io.set(id, 0.0, t))
}

rapid_vm::ext::layout! {
    static SET_DO: SetDoArgs = "SetDO" { s_delay: "SDelay", signal: "Signal", value: "Value" }
    static SET_GO: SetGoArgs = "SetGO" { s_delay: "SDelay", signal: "Signal", value: "Value", dvalue: "Dvalue" }
    static PULSE_DO: PulseDoArgs = "PulseDO" { high: "High", p_length: "PLength", signal: "Signal" }
    static GROUP_INFO: GroupInfoArgs = "GetGroupSignalInfo" {
        max_dvalue: "MaxDvalue", label: "Label", device_name: "DeviceName",
    }
}

/// `SetDO [\SDelay] | [\Sync] Signal Value`. `\Sync` waits until the physical output has
/// changed; the simulated output changes at once, so there is nothing to wait for.
fn set_do(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SET_DO;
    let id = signal(ctx, &args[at.signal])?;
    let value = ctx.num(&args[at.value])?;
    match ctx.opt_num(args.get(at.s_delay))? {
        Some(delay) => order(ctx, |io, t| io.set_delayed(id, value, t, delay)),
        None => order(ctx, |io, t| io.set(id, value, t)),
    }
}

/// `SetAO Signal Value`.
fn set_ao(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let id = signal(ctx, &args[0])?;
    let value = ctx.num(&args[1])?;
    order(ctx, |io, t| io.set(id, value, t))
}

/// `SetGO [\SDelay] Signal Value | Dvalue`.
fn set_go(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SET_GO;
    let id = signal(ctx, &args[at.signal])?;
    let value = if present(args.get(at.value)) { ctx.num(&args[at.value])? } else { ctx.num(&args[at.dvalue])? };
    match ctx.opt_num(args.get(at.s_delay))? {
        Some(delay) => order(ctx, |io, t| io.set_delayed(id, value, t, delay)),
        None => order(ctx, |io, t| io.set(id, value, t)),
    }
}

/// `InvertDO Signal`.
fn invert_do(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let id = signal(ctx, &args[0])?;
    order(ctx, |io, t| io.invert(id, t))
}

/// `PulseDO [\High] [\PLength] Signal` (0.2 s without `\PLength`).
fn pulse_do(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *PULSE_DO;
    let id = signal(ctx, &args[at.signal])?;
    let high = present(args.get(at.high));
    let length = ctx.opt_num(args.get(at.p_length))?;
    order(ctx, |io, t| io.pulse(id, high, length, t))
}

/// The value of a signal argument, reachable now (see [`signal`]).
fn read(ctx: &mut Ctx<'_>, arg: &Value) -> Result<f64, RapidError> {
    let id = signal(ctx, arg)?;
    Ok(ctx.resources.io().system.as_ref().and_then(|io| io.value(id)).unwrap_or(0.0))
}

/// `TestDI(Signal)`: whether a digital input is 1.
fn test_di(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let value = read(ctx, &args[0])?;
    Ok(Some(Value::Bool(value == 1.0)))
}

/// `GInputDnum(Signal)` / `GOutputDnum(Signal)`: a group's value as a dnum, exact for
/// groups of up to 32 bits (a num holds integers exactly only to 23 bits, manual §1.9).
fn group_dnum(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let value = read(ctx, &args[0])?;
    Ok(Some(Value::Dnum(value)))
}

/// `DInput`, `DOutput`, `GInput`, `GOutput`, `AInput`, `AOutput` (older forms of reading
/// a signal): the signal's value as a num.
fn signal_value(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let value = read(ctx, &args[0])?;
    Ok(Some(Value::Num(value as f32)))
}

/// `ValidIO(Signal)`: whether the signal can be used now: connected, and virtual or on
/// an enabled device.
fn valid_io(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let data = ctx.value(&args[0])?;
    // What the stimulus changed by now (a device disconnected) counts.
    let now = ctx.time;
    ctx.resources.io_mut().advance(now);
    let valid = handle_of(&data).is_some_and(|(id, _)| {
        ctx.resources.io().system.as_ref().is_some_and(|io| io.def(id).is_some() && io.is_running(id))
    });
    Ok(Some(Value::Bool(valid)))
}

/// `AliasIO FromSignal ToSignal`: connects signal data declared in RAPID to a signal of
/// the I/O configuration, named as text or by signal data connected already.
/// ERR_ALIASIO_DEF when FromSignal is no configured signal, ERR_ALIASIO_TYPE when the
/// two are of different signal types, ERR_NO_ALIASIO_DEF when FromSignal is signal data
/// that is not connected.
fn alias_io(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let Value::Ref(_) = &args[1] else { return Err(ctx.error(Err::ArgValue, "ToSignal must be signal data")) };
    let Value::Opaque(target) = ctx.value(&args[1])? else {
        return Err(ctx.error(Err::ArgValue, "ToSignal must be signal data"));
    };
    let from = match ctx.value(&args[0])? {
        Value::Str(name) => {
            let id = ctx.resources.io().system.as_ref().and_then(|io| io.id(&name));
            match id {
                Some(id) => id,
                None if ctx.resources.io().virtual_io => virtual_signal(ctx, &name, target.ty)?,
                None => return Err(ctx.error(Err::AliasIoDef, format!("no signal `{name}` in the I/O configuration"))),
            }
        }
        other => connected(ctx, &other)?,
    };
    let from_kind = ctx.resources.io().system.as_ref().and_then(|io| io.def(from)).map(|def| def.kind);
    let to_kind = ctx.resources.io().kinds.iter().find(|(ty, _)| *ty == target.ty).map(|(_, kind)| *kind);
    if from_kind.is_none() || from_kind != to_kind {
        return Err(ctx.error(Err::AliasIoType, "FromSignal and ToSignal are different kinds of signal"));
    }
    let connected = Opaque { ty: target.ty, state: OpaqueState::Handle(from | ALIAS_BIT) };
    ctx.store(&args[1], Value::Opaque(Box::new(connected)))?;
    Ok(None)
}

/// `--virtual-io`: a signal AliasIO names (a name computed at run time the text of
/// the program did not show) that the configuration lacks becomes a virtual signal of
/// the kind of the data it connects, told once.
fn virtual_signal(ctx: &mut Ctx<'_>, name: &str, ty: TypeId) -> Result<u32, RapidError> {
    let Some(kind) = ctx.resources.io().kinds.iter().find(|(t, _)| *t == ty).map(|(_, k)| *k) else {
        return Err(ctx.error(Err::AliasIoType, "ToSignal is no signal data"));
    };
    let mut def = rapid_io::SignalDef::new(name, kind);
    if matches!(kind, SignalKind::GI | SignalKind::GO) {
        // uncertain: a group's width is unknown without its configuration: 32 bits.
        def.group_bits = 32;
    }
    // `rapid run --virtual-io` always has an I/O system (an empty one at least).
    let Some(system) = ctx.resources.io_mut().system.as_mut() else {
        return Err(ctx.error(Err::AliasIoDef, format!("no signal `{name}`: there is no I/O system")));
    };
    let added = system.add_virtual(def);
    let id = added.map_err(|e| ctx.error(Err::AliasIoDef, format!("virtual signal `{name}`: {e:?}")))?;
    ctx.host.note(&format!("virtual signal {name} ({}) for AliasIO (--virtual-io)", kind_name(kind)));
    Ok(id)
}

/// The configuration's word for a signal kind (`-SignalType`).
pub fn kind_name(kind: SignalKind) -> &'static str {
    match kind {
        SignalKind::DI => "DI",
        SignalKind::DO => "DO",
        SignalKind::AI => "AI",
        SignalKind::AO => "AO",
        SignalKind::GI => "GI",
        SignalKind::GO => "GO",
    }
}

/// signalorigin values (manual §1.9 data type signalorigin).
// uncertain: the numbers 0, 1, 2 follow the order the manual lists the constants in.
const SIGORIG_NONE: f32 = 0.0;
const SIGORIG_CFG: f32 = 1.0;
const SIGORIG_ALIAS: f32 = 2.0;

/// `GetSignalOrigin(Signal, SignalName)`: SIGORIG_NONE for signal data that is not
/// connected (SignalName ""), SIGORIG_CFG for a signal of the I/O configuration,
/// SIGORIG_ALIAS for signal data AliasIO connected; SignalName is then the configured
/// signal's name.
fn get_signal_origin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let data = ctx.value(&args[0])?;
    let found = handle_of(&data).and_then(|(id, alias)| {
        let name = ctx.resources.io().system.as_ref()?.name(id)?.to_string();
        Some((if alias { SIGORIG_ALIAS } else { SIGORIG_CFG }, name))
    });
    let (origin, name) = found.unwrap_or((SIGORIG_NONE, String::new()));
    ctx.store(&args[1], Value::Str(name.into()))?;
    Ok(Some(Value::Num(origin)))
}

/// `GetGroupSignalInfo Signal [\MaxDvalue] [\Label] [\DeviceName]`: the largest value
/// of a group signal (2^bits - 1), its configured label and its device ("" for a virtual
/// signal). Configuration data, so a disabled device does not matter.
// uncertain: a signal that is not a group is refused with ERR_ARGVALERR.
fn get_group_signal_info(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let id = connected(ctx, &args[0])?;
    let def = ctx.resources.io().system.as_ref().and_then(|io| io.def(id)).cloned();
    let Some(def) = def.filter(|d| d.kind.is_group()) else {
        return Err(ctx.error(Err::ArgValue, "GetGroupSignalInfo needs a group signal (GI or GO)"));
    };
    let at = *GROUP_INFO;
    if present(args.get(at.max_dvalue)) {
        ctx.store(&args[at.max_dvalue], Value::Dnum(rapid_io::group_max(def.group_bits)))?;
    }
    if present(args.get(at.label)) {
        ctx.store(&args[at.label], Value::Str(def.label.as_str().into()))?;
    }
    if present(args.get(at.device_name)) {
        ctx.store(&args[at.device_name], Value::Str(def.device.unwrap_or_default().into()))?;
    }
    Ok(None)
}

/// `AliasIOReset Signal`: disconnects signal data AliasIO connected.
fn alias_io_reset(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let Value::Opaque(target) = ctx.value(&args[0])? else {
        return Err(ctx.error(Err::ArgValue, "Signal must be signal data"));
    };
    let reset = Opaque { ty: target.ty, state: OpaqueState::None };
    ctx.store(&args[0], Value::Opaque(Box::new(reset)))?;
    Ok(None)
}

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("AliasIO", alias_io),
        native("AliasIOReset", alias_io_reset),
        native("Set", set),
        native("Reset", reset),
        native("SetDO", set_do),
        native("SetAO", set_ao),
        native("SetGO", set_go),
        native("InvertDO", invert_do),
        native("PulseDO", pulse_do),
        native("TestDI", test_di),
        native("ValidIO", valid_io),
        native("GInputDnum", group_dnum),
        native("DInput", signal_value),
        native("DOutput", signal_value),
        native("GInput", signal_value),
        native("GOutput", signal_value),
        native("AInput", signal_value),
        native("AOutput", signal_value),
        native("GOutputDnum", group_dnum),
        native("GetSignalOrigin", get_signal_origin),
        native("GetGroupSignalInfo", get_group_signal_info),
    ],
};

#[cfg(test)]
mod tests {
    use rapid_io::{IoSystem, SignalDef, SignalKind};
    use rapid_vm::ext::{Resources, TaskHooks};

    use super::{IoAccess, HOOKS};

    /// A task's resources with do1 (id 0) and di1 (id 1); do1 set to 1 at 0 s, and a
    /// stimulus setting di1 to 1 at 0.5 s and to 0 at 3 s.
    fn resources() -> Resources {
        let defs = vec![SignalDef::new("do1", SignalKind::DO), SignalDef::new("di1", SignalKind::DI)];
        let mut system = IoSystem::new(defs, Vec::new()).expect("a valid configuration");
        let (do1, di1) = (system.id("do1").expect("do1"), system.id("di1").expect("di1"));
        system.set(do1, 1.0, 0.0).expect("do1 is an output the program may set");
        let mut resources = Resources::default();
        let io = resources.io_mut();
        io.system = Some(system);
        io.stimulus.extend([(0.5, di1, 1.0), (3.0, di1, 0.0)]);
        resources
    }

    #[test]
    fn signal_interrupts_get_the_changes_since_their_last_look_in_order() {
        let mut resources = resources();
        let mut changes = Vec::new();
        // By 1 s: do1 rose at 0 s, the stimulus raised di1 at 0.5 s.
        assert_eq!(HOOKS.signal_changes(&mut resources, 1.0, 0, &mut changes), Some(2));
        assert_eq!(changes, [(0, 1.0), (1, 1.0)]);
        changes.clear();
        // Nothing new by 2 s; the stimulus's next line is due at 3 s.
        assert_eq!(HOOKS.signal_changes(&mut resources, 2.0, 2, &mut changes), Some(2));
        assert!(changes.is_empty());
        assert_eq!(HOOKS.next_event(&mut resources), Some(3.0));
        assert_eq!(HOOKS.signal_changes(&mut resources, 3.0, 2, &mut changes), Some(3));
        assert_eq!(changes, [(1, 0.0)]);
    }

    #[test]
    fn a_task_without_io_has_no_signal_events() {
        let mut resources = Resources::default();
        assert_eq!(HOOKS.next_event(&mut resources), None);
        let mut changes = Vec::new();
        assert_eq!(HOOKS.signal_changes(&mut resources, 1.0, 0, &mut changes), Some(0));
        assert!(changes.is_empty());
    }
}
