//! The implementations of built-in instructions and functions, one file per family.
//! Their signatures (and how they take some arguments) are declared once in
//! rapid-lib's catalogue; each family registers its built-ins beside their code
//! (`FAMILY`, see `registry.rs`). A catalogue routine no family registers is listed
//! in `not_yet.rs` and refused by the compiler with "not supported by `rapid run` yet".

mod argname;
mod bits;
mod calendar;
mod clock;
pub mod controller;
mod dialogs;
mod dnheader;
mod events;
mod geometry;
pub mod interrupts;
pub mod io_visualize;
mod math;
mod matrix;
pub mod modules;
mod not_yet;
pub(crate) mod pendant;
pub mod pure;
mod random;
mod rawbytes;
mod registry;
pub mod signature;
pub use registry::{compiled, native, out_of_step, Builtin, Builtins, Compiled, Family};
pub mod spy;
mod strdig;
mod strformat;
mod strings;
mod symbols;
pub mod wait;
pub use strings::{read_literal, value_literal};
pub use symbols::same_type;
pub mod symsearch;
mod sysinfo;
mod system;
pub mod tasks;
pub mod texttab;
pub mod typenames;

use rapid_sema::types::TypeId;

use crate::errnames::Err;
use crate::error::RapidError;
use crate::exec::storage::Storage;
use crate::host::Host;
use crate::ops::OpTypes;
use crate::value::{Record, Value};

/// Index of a built-in in [`TABLE`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BuiltinId(pub u16);

/// Arguments arrive in parameter order: values for IN parameters, `Value::Ref` for
/// VAR/INOUT/PERS, `Value::Absent` for optional ones not passed, `Value::SwitchOn`.
pub type BuiltinFn = fn(&mut Ctx<'_>, &[Value]) -> Result<Option<Value>, RapidError>;

/// What a built-in may touch.
pub struct Ctx<'a> {
    pub storage: &'a mut Storage,
    pub host: &'a mut dyn Host,
    pub types: OpTypes,
    /// Virtual time in seconds.
    pub time: f64,
    /// Set by waiting instructions: how long to wait (virtual seconds).
    pub wait: Option<f64>,
    /// Wall-clock seconds a built-in already spent waiting on the outside world (a
    /// socket): the controller clock moves on by this much, on success and on error,
    /// with no further wait (`--realtime` must not sleep it twice).
    pub waited: f64,
    /// Set by Stop and ExitCycle.
    pub stop: StopKind,
    pub errnos: &'a rustc_hash::FxHashMap<&'static str, i32>,
    /// Which globals are persistents.
    pub pers_globals: &'a [bool],
    /// RETRYs left in the calling routine's error handler (RemainingRetries).
    pub retries_left: u32,
    /// Set by ResetRetryCount.
    pub reset_retries: bool,
    /// Set by SkipWarn.
    pub skip_warn: bool,
    /// The next free booked error number (BookErrNo).
    pub next_booked: &'a mut i32,
    /// The event log (ErrWrite, ErrLog, ErrRaise).
    pub events: &'a mut crate::events::EventLog,
    /// Module-level data by lower-case name.
    pub data_by_name: &'a rustc_hash::FxHashMap<String, NamedData>,
    /// Procedures by lower-case name, and the routines (Move*Sync calls one by name).
    pub procs_by_name: &'a rustc_hash::FxHashMap<String, u32>,
    pub routines: &'a [Option<std::rc::Rc<crate::ir::Code>>],
    /// The routine that made the call (ERRSTR_CONTEXT).
    pub routine: &'a str,
    /// Wall-clock seconds since 1970 when the task was given its world (CDate, CTime).
    pub wall_epoch: f64,
    /// What the task has outside the interpreter (the extensions' state among it).
    pub resources: &'a mut Resources,
    /// The call chain, outermost first; the last frame made the call (ExecHandler,
    /// ExecLevel).
    pub(crate) chain: &'a [crate::exec::Frame],
    /// The built-ins the task runs with (to name the one a call site calls).
    pub builtins: &'a Builtins,
}

/// What the task holds outside the interpreter: each family keeps its own table,
/// referred to by `OpaqueState::Handle` in the program's data (an extension's, such
/// as the controller's iodev, dir and socketdev tables, in `extensions`).
#[derive(Default)]
pub struct Resources {
    /// The file devices (`HOME:` ...) on the world's disk, and the loaded modules' files.
    pub devices: crate::world::devices::Devices,
    /// Installed user text tables (kept at PP to Main, as the controller keeps them).
    pub texttab: texttab::TextTabState,
    /// The task's module data by module, and the search SetDataSearch started.
    pub symsearch: symsearch::SymSearchState,
    /// The execution log SpyStart opened (ended at PP to Main, as on the controller).
    pub spy: spy::SpyState,
    pub modules: modules::ModuleState,
    /// Rand's generator (kept across PP to Main: the sequence goes on).
    pub random: random::RandomState,
    /// The waiting instruction under way (WaitDI, WaitTime while interrupts may come,
    /// a dialog a front end answers later …): (call depth, pc, started at); see
    /// `wait.rs`.
    pub waiting: Option<(usize, u32, f64)>,
    /// The operator's answers to pendant dialogs at given times (a stimulus), in
    /// time order (the controller's tasks share them: [`Shared::answers`]).
    pub answers: std::collections::VecDeque<(f64, String)>,
    /// Notes for the run's user not yet told (see [`Resources::note_later`]).
    notes: Vec<String>,
    /// The message boxes of waits with `\Visualize` under way, one per call depth.
    pub(crate) boxes: Vec<io_visualize::ShownBox>,
    /// The task's interrupts (deleted at PP to Main).
    pub interrupts: interrupts::InterruptState,
    /// Which task this is, and what the core shares with the other tasks (the task
    /// names, the requests to the controller); the rest of multitasking is an
    /// extension's (rapid-tasks).
    pub tasks: tasks::TaskPlace,
    /// The task's types by name, by which a value leaves the task (a RAPID Message
    /// Queue message: the controller's RMQ binding) or is built by type name (the
    /// robot's data).
    pub type_names: typenames::TypeNames,
    /// The operating mode, speed override and PP flags (kept at PP to Main).
    pub controller: controller::ControllerState,
    /// The embedder's extensions' own state (`crate::embed`).
    pub extensions: crate::embed::Extensions,
    /// The extensions' state every task of a controller shares, lent to the task
    /// while it runs (`Shared::lent`, swapped whole by [`Resources::exchange_shared`]);
    /// a task alone keeps its own here.
    pub lent: crate::embed::Extensions,
}

/// What the tasks of one controller share: handed to the task that runs, so each
/// task's built-ins see the one I/O system and the one set of sync points.
#[derive(Default)]
pub struct Shared {
    /// The extensions' shared state (the signals: rapid-signals' `SharedIo`), swapped
    /// in by their `TaskHooks::exchange_shared`.
    pub extensions: crate::embed::Extensions,
    /// The operator's timed answers to pendant dialogs (a stimulus).
    pub answers: std::collections::VecDeque<(f64, String)>,
    /// The task names, the requests to the controller, the controller-wide event log.
    pub tasks: tasks::SharedTasks,
    /// The extensions' shared state the core hands over whole (one swap of the map
    /// per exchange, however many extensions keep theirs here: multitasking's
    /// `SharedTasking`, the RMQ queues), each found by type.
    pub lent: crate::embed::Extensions,
}

impl Resources {
    /// Ends what the task holds open (end of program, PP to Main: the start-up table
    /// of §1.2.2 closes files and sockets, which the extensions close through
    /// `TaskState::close_all`).
    pub fn close_all(&mut self) {
        self.symsearch.end_search();
        self.spy.stop();
        self.modules.close_all();
        self.interrupts.clear();
        self.extensions.close_all(&mut self.lent);
    }

    /// Swaps the controller's shared state with the task's (hand in, take back): the
    /// core's part; the extensions' part goes with it in `Vm::exchange_shared`.
    pub fn exchange_shared(&mut self, shared: &mut Shared) {
        std::mem::swap(&mut self.answers, &mut shared.answers);
        std::mem::swap(&mut self.tasks.shared, &mut shared.tasks);
        std::mem::swap(&mut self.lent, &mut shared.lent);
    }

    /// The waiting instruction under way is over (it ended or timed out).
    pub fn end_wait(&mut self) {
        self.waiting = None;
    }

    /// When the waiting instruction under way (WaitDI …) began, if one is.
    pub fn wait_started(&self) -> Option<f64> {
        self.waiting.map(|(_, _, at)| at)
    }

    /// A note for the run's user (on stderr in `rapid run`), told when the task next
    /// runs: what `--virtual-io` made of a signal, for one.
    pub fn note_later(&mut self, text: String) {
        self.notes.push(text);
    }

    pub(crate) fn take_notes(&mut self) -> Vec<String> {
        std::mem::take(&mut self.notes)
    }
}

impl Ctx<'_> {
    pub fn error(&self, err: Err, message: impl Into<String>) -> RapidError {
        RapidError {
            errno: self.errnos.get(err.name()).copied().unwrap_or(0),
            name: err.name(),
            message: message.into(),
            fatal: false,
            event: None,
        }
    }

    /// The value of an argument (through a reference).
    pub fn value(&self, arg: &Value) -> Result<Value, RapidError> {
        match arg {
            Value::Ref(place) => self.storage.get(place).cloned().map_err(|(e, m)| self.error(e, m)),
            other => Ok(other.clone()),
        }
    }

    pub fn num(&self, arg: &Value) -> Result<f64, RapidError> {
        // Read in place: no copy of the argument on this hot path.
        let value = match arg {
            Value::Ref(place) => self.storage.get(place).map_err(|(e, m)| self.error(e, m))?,
            other => other,
        };
        match value {
            Value::Num(n) => Ok(f64::from(*n)),
            Value::Dnum(d) => Ok(*d),
            _ => Err(self.error(Err::ArgValue, "a numeric argument was expected")),
        }
    }

    pub fn opt_num(&self, arg: Option<&Value>) -> Result<Option<f64>, RapidError> {
        match arg {
            None | Some(Value::Absent) => Ok(None),
            Some(v) => self.num(v).map(Some),
        }
    }

    /// Resolves RAPID path `text` on its device (`crate::world::devices`), after the
    /// extensions wrote out what the task wrote but still holds in write buffers
    /// ([`crate::embed::TaskHooks::flush_files`]): whatever looks at a path next sees it.
    pub fn resolve_path(
        &mut self,
        text: &str,
    ) -> Result<crate::world::devices::Resolved, crate::world::devices::PathFault> {
        for hooks in self.builtins.hooks() {
            hooks.flush_files(self.resources);
        }
        self.resources.devices.resolve(text)
    }

    /// The shell of a non-value argument (iodev, dir, socketdev, loadsession …) and
    /// the handle it holds, if any; `what` names the type for the error.
    pub fn handle_arg(&self, arg: &Value, what: &str) -> Result<(crate::value::Opaque, Option<u32>), RapidError> {
        match self.value(arg)? {
            Value::Opaque(opaque) => {
                let handle = match opaque.state {
                    crate::value::OpaqueState::Handle(h) => Some(h),
                    _ => None,
                };
                Ok((*opaque, handle))
            }
            _ => Err(self.error(Err::ArgValue, format!("{what} was expected"))),
        }
    }

    /// The handle an opaque argument (iodev, socketdev, dir) holds, read in place
    /// (file and socket built-ins run in tight loops); None when it holds none.
    pub fn handle_only(&self, arg: &Value, what: &str) -> Result<Option<u32>, RapidError> {
        let value = match arg {
            Value::Ref(place) => self.storage.get(place).map_err(|(e, m)| self.error(e, m))?,
            other => other,
        };
        match value {
            Value::Opaque(opaque) => Ok(match opaque.state {
                crate::value::OpaqueState::Handle(h) => Some(h),
                _ => None,
            }),
            _ => Err(self.error(Err::ArgValue, format!("{what} was expected"))),
        }
    }

    /// A string argument without copying it.
    pub fn str_arg(&self, arg: &Value) -> Result<std::rc::Rc<str>, RapidError> {
        let value = match arg {
            Value::Ref(place) => self.storage.get(place).map_err(|(e, m)| self.error(e, m))?,
            other => other,
        };
        match value {
            Value::Str(s) => Ok(s.clone()),
            _ => Err(self.error(Err::ArgValue, "a string argument was expected")),
        }
    }

    pub fn string(&self, arg: &Value) -> Result<String, RapidError> {
        match self.value(arg)? {
            Value::Str(s) => Ok(s.to_string()),
            _ => Err(self.error(Err::ArgValue, "a string argument was expected")),
        }
    }

    /// Writes through a VAR/INOUT/PERS argument.
    pub fn store(&mut self, arg: &Value, value: Value) -> Result<(), RapidError> {
        let Value::Ref(place) = arg else { return Err(self.error(Err::ArgValue, "this argument must be data")) };
        let place = place.clone();
        self.storage.set(&place, value).map_err(|(e, m)| self.error(e, m))
    }

    pub fn pos(&self, x: f32, y: f32, z: f32) -> Value {
        Value::Record(std::rc::Rc::new(Record {
            ty: self.types.pos,
            fields: vec![Value::Num(x), Value::Num(y), Value::Num(z)],
        }))
    }

    pub fn pos_ty(&self) -> TypeId {
        self.types.pos
    }

    /// The data object passed for parameter `param` of the built-in being called,
    /// followed through the callers to the argument first passed for it (GripLoad's
    /// payload, a syncident's name).
    pub fn arg_name(&self, param: usize) -> Option<std::rc::Rc<str>> {
        argname::original_name(self.chain, param)
    }

    /// Whether the call is made inside a TRAP routine (or something it called).
    pub fn in_trap(&self) -> bool {
        self.chain.iter().any(|f| f.is_trap())
    }

    /// Where the call is made: the depth of the call chain and the calling routine's
    /// instruction index (a built-in that runs again, `StopKind::Repeat`, finds its
    /// own earlier call by it).
    pub fn call_place(&self) -> (usize, u32) {
        (self.chain.len(), self.chain.last().map_or(0, |f| f.position().1))
    }

    /// The built-in the running routine is calling and its statement: (name, file,
    /// span), as the event log places what a built-in logs.
    pub fn instruction_here(&self) -> (&'static str, usize, rapid_syntax::Span) {
        use crate::ir::{Callee, Instr};
        let Some(frame) = self.chain.last() else { return ("", usize::MAX, rapid_syntax::Span::default()) };
        let (code, pc) = frame.position();
        // The innermost statement holding `pc` (as `Code::stmt_at`), found by halving:
        // statements are in order of their start, and a generated module of 100,000
        // moves in one routine must not cost a scan per move.
        let upto = code.stmts.partition_point(|s| s.start <= pc);
        let span = code.stmts[..upto].iter().rev().find(|s| pc < s.end).map_or(code.span, |s| s.span);
        let name = match code.instrs.get(pc as usize) {
            Some(Instr::Call(site)) => match code.sites.get(*site as usize).map(|s| s.callee) {
                Some(Callee::Builtin(id)) => self.builtins.name(id),
                _ => "",
            },
            _ => "",
        };
        (name, code.file, span)
    }
}

/// Module-level data that built-ins find by name (ErrRaise, GetDataVal, SetDataVal).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NamedData {
    pub global: u32,
    pub constant: bool,
}

/// How a built-in ends the normal flow.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopKind {
    None,
    /// Stop (and Break): halt; a restart continues with the next instruction.
    Stop,
    /// ExitCycle: end the cycle (UNDO handlers run), PP back to main.
    ExitCycle,
    /// A waiting instruction whose condition does not hold yet (WaitDI …): wait for
    /// `Ctx::wait`, then run the statement again from its start.
    Repeat,
    /// StartMoveRetry: RETRY from the ERROR handler the call is in.
    Retry,
}

/// Whether every extension stands still before a stop-point instruction goes on
/// (WaitTime and WaitSyncTask with `\InPos`): `false` (the extension set a wait and
/// a repeat) while the robot still moves.
pub fn stands_still(ctx: &mut Ctx<'_>) -> Result<bool, RapidError> {
    let set: &Builtins = ctx.builtins;
    for hooks in set.hooks() {
        if !hooks.stands_still(ctx)? {
            return Ok(false);
        }
    }
    Ok(true)
}

/// ExitCycle ends the cycle: every extension drops what it has under way.
pub(crate) fn exit_cycle_hooks(ctx: &mut Ctx<'_>) -> Result<(), RapidError> {
    let set: &Builtins = ctx.builtins;
    for hooks in set.hooks() {
        hooks.exit_cycle(ctx)?;
    }
    Ok(())
}

/// Present means passed: not absent.
pub fn present(arg: Option<&Value>) -> bool {
    arg.is_some_and(|a| !a.is_absent())
}

/// The language's families; a built-in's id is its position in the concatenation of
/// these and then the extensions' families (`Builtins::new`). A new family file of
/// the core adds its `FAMILY` here; an embedder's goes into its `Extension`.
pub(crate) static CORE_FAMILIES: &[&Family] = &[
    &crate::compile::call::FAMILY,
    &pendant::FAMILY,
    &dialogs::FAMILY,
    &rawbytes::FAMILY,
    &system::FAMILY,
    &events::FAMILY,
    &clock::FAMILY,
    &math::FAMILY,
    &geometry::FAMILY,
    &bits::FAMILY,
    &strings::FAMILY,
    &calendar::FAMILY,
    &symbols::FAMILY,
    &matrix::FAMILY,
    &sysinfo::FAMILY,
    &strdig::FAMILY,
    &strformat::FAMILY,
    &argname::FAMILY,
    &texttab::FAMILY,
    &symsearch::FAMILY,
    &dnheader::FAMILY,
    &modules::FAMILY,
    &random::FAMILY,
    &interrupts::FAMILY,
    &spy::FAMILY,
    &controller::FAMILY,
];

static CORE: std::sync::LazyLock<std::sync::Arc<Builtins>> =
    std::sync::LazyLock::new(|| std::sync::Arc::new(Builtins::new(&[])));

impl Builtins {
    /// The language's built-ins alone, with no extension: what a program that moves
    /// no robot needs. Built once and shared (it never changes). An embedder's set
    /// adds its extensions (`Builtins::new`; the controller's is
    /// `rapid_controller::builtin_set::standard`).
    pub fn core() -> std::sync::Arc<Builtins> {
        CORE.clone()
    }
}

/// Why `rapid run` does not run the catalogue routine `name` yet, if it is listed.
pub fn not_supported_reason(name: &str) -> Option<&'static str> {
    not_yet::reason(name)
}

/// Why a program calling `name`, a routine of catalogue chapter `chapter`, is refused
/// at load when the chapter is a software option's: no option is simulated, and a
/// refusal before anything runs leaves nothing half-done.
pub fn option_refusal(name: &str, chapter: &str) -> Option<String> {
    let option = rapid_lib::catalogue::options::of_chapter(chapter)?;
    Some(format!("`{name}` {OPTION_REFUSAL_MIDDLE}{}{OPTION_REFUSAL_TAIL}", option.name))
}

/// The parts of an [`option_refusal`] message (`crate::refusals` reads them back to
/// give one refusal per option).
pub(crate) const OPTION_REFUSAL_MIDDLE: &str = "belongs to option ";
pub(crate) const OPTION_REFUSAL_TAIL: &str = ", which `rapid run` does not simulate";
