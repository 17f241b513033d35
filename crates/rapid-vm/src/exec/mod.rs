//! The executor: frames on a `Vec`, a budgeted run loop that can stop after any
//! instruction, and RAPID error recovery by table lookup (§1.12), never by Rust
//! unwinding. Frame layout on the value stack:
//!
//! ```text
//! frame.base ─► | param 0 | … | param n-1 | data / loop / temp slots | operands … |
//! ```
//! A VAR, INOUT or PERS parameter slot holds `Value::Ref(place)`; loads and stores
//! go through it.

pub mod backward;
mod call;
mod error_watch;
pub use error_watch::ErrorStop;
mod fast;
mod frames;
mod hooks;
pub mod inspect;
mod instr;
mod interrupts;
mod kernel;
mod late;
mod log;
mod module_check;
pub mod modules;
mod num;
mod repeat;
mod setup;
mod shared;
mod spy;
mod statement;
mod stop;
pub mod storage;
pub(crate) mod undo;
mod world;

use std::rc::Rc;

use rustc_hash::FxHashMap;

use crate::builtins::Ctx;
use crate::errnames::Err;
use crate::error::RapidError;
use crate::ir::{Code, Instr, StmtRange};
use crate::ops::{self, OpTypes};
use crate::value::{Array, PathStep, Place, Root, Value};
pub(crate) use frames::Frame;
use frames::Frames;
use storage::{coerce_like, index_place, Storage};

/// RETRY may restart a failing instruction this many times (§1.12: "up to four").
pub const MAX_RETRIES: u32 = 4;
/// Calls nested deeper than this stop the program (runaway recursion).
pub const MAX_CALL_DEPTH: usize = rapid_limits::CALL_DEPTH;
/// The first number BookErrNo hands out.
const FIRST_BOOKED_ERRNO: i32 = 5000;

/// Whether `n` is a number BookErrNo has given out (the next free one is `next_booked`).
pub(crate) fn is_booked(n: i32, next_booked: i32) -> bool {
    (FIRST_BOOKED_ERRNO..next_booked).contains(&n)
}

/// Why `run` returned.
#[derive(Debug, Clone, PartialEq)]
pub enum Exit {
    /// The program ended: main returned or EXIT ran.
    Done,
    /// Stop (or Break): execution halts; a restart would continue.
    Stopped,
    /// The step budget is spent; call `run` again to go on.
    Budget,
    /// A waiting instruction: advance the clock by this many seconds, then `run`.
    Wait(f64),
    /// An error no ERROR handler handled; the system error handler stops the program.
    Unhandled(Unhandled),
    /// ExitCycle: the cycle ended (UNDO handlers ran); a continuous run would start
    /// main again, a single-cycle run stops.
    CycleEnded,
}

/// An error that reached the system error handler, with where it was raised last: the
/// failing statement (however deep in calls, traps or functions it was), or the RAISE
/// of an ERROR handler that passed it on; `routine` is the routine holding it.
#[derive(Debug, Clone, PartialEq)]
pub struct Unhandled {
    pub error: RapidError,
    pub routine: String,
    pub file: usize,
    pub span: rapid_syntax::Span,
}

/// An error being handled by a frame's ERROR handler.
#[derive(Debug, Clone)]
struct ActiveError {
    error: RapidError,
    stmt: StmtRange,
    /// Where the error was raised last, for the system error handler if this handler
    /// ends without handling it.
    raised_at: RaisedAt,
    /// The event-log warning a handled error leaves (§1.12), until SkipWarn drops it.
    warning: Option<u64>,
}

/// Where an error was raised last: the statement that failed, or the RAISE of an
/// ERROR handler that passed the error on. An error that goes up to a caller without
/// being handled keeps it; the system error handler reports it (§1.12).
#[derive(Debug, Clone)]
struct RaisedAt {
    code: Rc<Code>,
    span: rapid_syntax::Span,
}

/// One program task's interpreter.
pub struct Vm {
    routines: Vec<Option<Rc<Code>>>,
    procs_by_name: FxHashMap<String, u32>,
    storage: Storage,
    frames: Frames,
    types: OpTypes,
    errnos: FxHashMap<&'static str, i32>,
    errno_global: Option<u32>,
    /// INTNO, set when a trap starts.
    intno_global: Option<u32>,
    /// Which globals are persistents (IsPers, IsVar).
    pers_globals: Vec<bool>,
    /// Reused for the arguments of calls that need rearranging.
    arg_scratch: Vec<Value>,
    next_booked: i32,
    exiting: bool,
    /// The exit under way ends the cycle (ExitCycle) rather than the program (EXIT).
    cycle_exit: bool,
    /// The next call enters its routine's BACKWARD handler (backward execution);
    /// the caller's PP then returns to this statement start.
    backward_entry: Option<u32>,
    /// For program events: the load-time code and the values data has before it.
    init: Option<(Rc<Code>, Vec<Value>)>,
    /// Virtual time in seconds.
    pub time: f64,
    /// Instructions executed so far.
    pub steps: u64,
    /// The last `Exit::Wait` re-checks its condition when resumed (WaitDI, WaitSyncTask),
    /// so another task's change may resume it early; a delay (WaitTime) may not be.
    pub wait_rechecks: bool,
    /// What ErrWrite, ErrLog and ErrRaise logged, oldest first.
    events: crate::events::EventLog,
    /// Module-level data by lower-case name (ErrRaise names its errnum as text).
    data_by_name: FxHashMap<String, crate::builtins::NamedData>,
    /// Wall-clock seconds since 1970 on the world's clock when the world was given
    /// ([`Vm::set_world`]): the calendar clock is this plus the controller time.
    wall_epoch: f64,
    world_given: bool, // Vm::set_world gave the task its outside world
    /// What the task has outside the interpreter (its file devices, signals, the
    /// extensions' state: files, sockets, the robot ...).
    resources: crate::builtins::Resources,
    /// The program's sources and the modules loaded at run time (Load, UnLoad).
    modules: modules::TaskModules,
    /// Statements the execution log (SpyStart) has seen start and not yet end.
    spy_open: Vec<spy::SpyOpen>,
    /// Boxes of references passed to VAR/INOUT/PERS parameters, returned when their
    /// routine returns: a call with such arguments allocates nothing. Boxes, not
    /// places, because `Value::Ref` holds a box and is handed one as it is.
    #[allow(clippy::vec_box)]
    place_pool: Vec<Box<Place>>,
    /// A debugger's exception breakpoints (`error_watch.rs`).
    error_watch: error_watch::ErrorWatch,
    /// The built-ins the task's call sites name by id, with the extensions' hooks.
    builtins: std::sync::Arc<crate::builtins::Builtins>,
    /// Whether the program owed an extension a wait when the last built-in returned.
    held_after_call: bool,
}

impl Vm {
    /// A VM for compiled routines; `globals` already hold their initial values.
    pub fn new(
        builtins: std::sync::Arc<crate::builtins::Builtins>,
        routines: Vec<Option<Code>>,
        procs_by_name: FxHashMap<String, u32>,
        globals: Vec<Value>,
        types: OpTypes,
        errnos: FxHashMap<&'static str, i32>,
        errno_global: Option<u32>,
    ) -> Vm {
        let mut vm = Vm {
            routines: routines.into_iter().map(|c| c.map(Rc::new)).collect(),
            procs_by_name,
            storage: Storage { globals: storage::Globals::new(globals), stack: Vec::new() },
            frames: Frames::default(),
            types,
            errnos,
            errno_global,
            intno_global: None,
            pers_globals: Vec::new(),
            arg_scratch: Vec::new(),
            next_booked: FIRST_BOOKED_ERRNO,
            exiting: false,
            cycle_exit: false,
            backward_entry: None,
            init: None,
            time: 0.0,
            steps: 0,
            wait_rechecks: false,
            events: crate::events::EventLog::default(),
            data_by_name: FxHashMap::default(),
            wall_epoch: 0.0, // the closed world's clock (1970) until set_world
            world_given: false,
            resources: crate::builtins::Resources::default(),
            modules: modules::TaskModules::default(),
            spy_open: Vec::new(),
            place_pool: Vec::new(),
            error_watch: error_watch::ErrorWatch::default(),
            builtins,
            held_after_call: false,
        };
        let builtins = vm.builtins.clone();
        builtins.init_task(&mut vm.resources);
        vm
    }

    /// The task's resources (to configure its devices, or the extensions' state).
    pub fn resources_mut(&mut self) -> &mut crate::builtins::Resources {
        &mut self.resources
    }

    /// The task's resources (devices, signals, the extensions' state), to look at.
    pub fn resources(&self) -> &crate::builtins::Resources {
        &self.resources
    }

    /// The event log written so far, oldest first.
    pub fn event_log(&self) -> &[crate::events::Event] {
        self.events.entries()
    }

    /// Whether the program ended by EXIT (which forbids a restart: a continuous run
    /// stops there) rather than by the end of its entry routine or ExitCycle.
    pub fn ended_by_exit(&self) -> bool {
        self.exiting && !self.cycle_exit && self.frames.is_empty()
    }

    /// Runs `code` with no arguments as the first frame (the entry routine or the
    /// load-time initialisers).
    pub fn start(&mut self, code: Rc<Code>) {
        self.forget_error_stop();
        self.frames.clear();
        self.storage.stack.clear();
        self.exiting = false;
        self.cycle_exit = false;
        self.push_frame(code, Vec::new());
    }

    /// Remembers how data gets its initial values, for [`Vm::pp_to_main`].
    pub fn set_init(&mut self, code: Rc<Code>, defaults: Vec<Value>) {
        self.init = Some((code, defaults));
    }

    /// "PP to Main" (§1.2.2 start-up table): UNDO handlers of the routines still
    /// running are run (§1.13); constants and variables get their initial values
    /// again; persistents keep theirs; execution is set to start `entry`.
    pub fn pp_to_main(&mut self, host: &mut dyn crate::host::Host, entry: u32) -> Result<(), Unhandled> {
        if !self.frames.is_empty() {
            self.exiting = true;
            if self.continue_exit().is_none() {
                if let Exit::Unhandled(u) = self.run(host, u64::MAX) {
                    return Err(u);
                }
            }
        }
        self.resources.close_all();
        if let Some((code, defaults)) = self.init.clone() {
            let kept: Vec<(u32, Value)> = self
                .pers_globals
                .iter()
                .enumerate()
                .filter(|(_, &pers)| pers)
                .filter_map(|(idx, _)| self.storage.globals.get(idx as u32).map(|v| (idx as u32, v.clone())))
                .collect();
            self.storage.globals.replace(defaults);
            self.start(code);
            if let Exit::Unhandled(u) = self.run(host, u64::MAX) {
                return Err(u);
            }
            self.modules_at_pp_to_main(host)?;
            for (idx, value) in kept {
                if let Some(slot) = self.storage.globals.get_mut(idx) {
                    *slot = value;
                }
            }
            self.extensions_data_initialised();
        }
        self.start_routine(entry);
        Ok(())
    }

    /// Starts routine `idx` (which takes no arguments).
    pub fn start_routine(&mut self, idx: u32) -> bool {
        match self.routines.get(idx as usize).cloned().flatten() {
            Some(code) => {
                self.start(code);
                true
            }
            None => false,
        }
    }

    fn errno(&self, err: Err) -> i32 {
        self.errnos.get(err.name()).copied().unwrap_or(0)
    }

    fn error(&self, err: Err, message: impl Into<String>) -> RapidError {
        RapidError { errno: self.errno(err), name: err.name(), message: message.into(), fatal: false, event: None }
    }

    fn fault(&self, (err, message): (Err, String)) -> RapidError {
        self.error(err, message)
    }

    /// Executes at most `budget` instructions.
    pub fn run(&mut self, host: &mut dyn crate::host::Host, budget: u64) -> Exit {
        let mut remaining = budget;
        // Notes about the run made where no host was at hand (the virtual signals of
        // `--virtual-io`), told once.
        for text in self.resources.take_notes() {
            host.note(&text);
        }
        // Messages another task sent while this one did not run.
        self.dispatch_messages();
        // The task stood stopped at an error no handler takes: now it ends with it.
        if let Some(exit) = self.take_pending_end() {
            self.log_if_unhandled(&exit);
            return exit;
        }
        while remaining > 0 {
            if self.frames.is_empty() {
                return Exit::Done;
            }
            // While the program owes the robot the rest of a move's wait (a trap cut it
            // short), one instruction at a time too: the wait resumes when the trap returns.
            let watched = self.resources.interrupts.active() || self.program_hold().is_some();
            let outcome = if self.resources.spy.is_active() || watched {
                // The execution log sees every statement, and interrupts are looked for
                // before every instruction: one instruction at a time.
                remaining -= 1;
                self.steps += 1;
                if watched {
                    self.poll_interrupts();
                    self.enter_trap_if_due();
                    if let Some(wait) = self.motion_hold() {
                        return Exit::Wait(wait);
                    }
                }
                let outcome = self.resume_or_step(host);
                self.spy_forget_if_stopped();
                outcome
            } else {
                match self.resume_or_run_fast(&mut remaining, host) {
                    fast::Fast::Budget => break,
                    fast::Fast::Step => self.step(host), // pc needs the general path
                    fast::Fast::Called(outcome) => outcome,
                }
            };
            let exit = match outcome {
                Ok(exit) => exit,
                Err(error) => self.raise(error),
            };
            if let Some(exit) = exit {
                self.log_if_unhandled(&exit);
                return exit;
            }
        }
        if self.frames.is_empty() {
            Exit::Done
        } else {
            Exit::Budget
        }
    }

    fn frame(&self) -> &Frame {
        self.frames.last().expect("a running frame")
    }

    fn frame_mut(&mut self) -> &mut Frame {
        self.frames.last_mut().expect("a running frame")
    }

    fn pop(&mut self) -> Value {
        self.storage.stack.pop().unwrap_or(Value::Absent)
    }

    fn push(&mut self, value: Value) {
        self.storage.stack.push(value);
    }

    fn pop_num(&mut self) -> Result<f64, RapidError> {
        let value = self.pop();
        value.as_f64().ok_or_else(|| self.error(Err::ArgValue, "a number was expected"))
    }

    /// Executes one instruction of the top frame.
    fn step(&mut self, host: &mut dyn crate::host::Host) -> Result<Option<Exit>, RapidError> {
        let (code, pc, base) = {
            let frame = self.frame();
            (frame.code.clone(), frame.pc, frame.base)
        };
        let Some(&instr) = code.instrs.get(pc as usize) else {
            return Err(RapidError::fatal("the program counter left its routine"));
        };
        let mut next = pc + 1;
        match instr {
            Instr::Const(i) => self.push(code.consts[i as usize].clone()),
            Instr::Aggregate(k) => self.push(instr::aggregate(&code, k)?),
            // The fast loop runs kernels; here the statement's general code, which
            // follows, does the work.
            Instr::KernelStore { .. } | Instr::KernelBranch { .. } | Instr::KernelReturn { .. } => {}
            Instr::LoadLocal(slot) => {
                let value = self.load_local(base + slot)?;
                self.push(value);
            }
            Instr::StoreLocal(slot) => {
                let value = self.pop();
                self.store_local(base + slot, value)?;
            }
            Instr::LoadGlobal(idx) => {
                let value = self.storage.globals.get(idx).cloned().unwrap_or(Value::Absent);
                self.push(value);
            }
            Instr::StoreGlobal(idx) => {
                let value = self.pop();
                let place = Place { root: Root::Global(idx), path: Vec::new() };
                self.storage.set(&place, value).map_err(|f| self.fault(f))?;
            }
            Instr::PlaceLocal(slot) => {
                let (root, path) = match &self.storage.stack[(base + slot) as usize] {
                    Value::Ref(place) => (place.root, place.path.clone()),
                    Value::Absent => return Err(self.error(Err::NotPresent, "an optional parameter was not passed")),
                    _ => (Root::Stack(base + slot), Vec::new()),
                };
                let place = self.pooled_place(root, &path);
                self.push(Value::Ref(place));
            }
            Instr::PlaceGlobal(idx) => {
                let place = self.pooled_place(Root::Global(idx), &[]);
                self.push(Value::Ref(place));
            }
            Instr::PlaceField(field) => {
                if let Some(Value::Ref(place)) = self.storage.stack.last_mut() {
                    place.path.push(PathStep::Field(field));
                }
            }
            Instr::PlaceIndex(n) => {
                let indices = self.pop_indices(n)?;
                let Value::Ref(place) = self.pop() else { return Err(RapidError::fatal("no place to index")) };
                let place = index_place(&self.storage, *place, &indices).map_err(|f| self.fault(f))?;
                self.push(Value::Ref(Box::new(place)));
            }
            Instr::LoadPlace => {
                let Value::Ref(place) = self.pop() else { return Err(RapidError::fatal("no place to load")) };
                let value = self.storage.get(&place).map_err(|f| self.fault(f))?.clone();
                self.push(value);
            }
            Instr::StorePlace => {
                let value = self.pop();
                let Value::Ref(place) = self.pop() else { return Err(RapidError::fatal("no place to store")) };
                self.storage.set(&place, value).map_err(|f| self.fault(f))?;
            }
            Instr::LoadElem { global, slot, n } => {
                let indices = self.pop_index_array(n)?;
                let value = self.element(global, base + slot, slot, &indices[..n as usize])?.clone();
                self.push(value);
            }
            Instr::StoreElem { global, slot, n } => {
                let value = self.pop();
                let indices = self.pop_index_array(n)?;
                let place = self.element_place(global, base + slot, slot, &indices[..n as usize])?;
                self.storage.set(&place, value).map_err(|f| self.fault(f))?;
            }
            Instr::Field(field) => {
                let Value::Record(record) = self.pop() else { return Err(self.error(Err::ArgValue, "not a record")) };
                // A record nobody else holds gives up its component; a shared one copies it.
                let value = match std::rc::Rc::try_unwrap(record) {
                    Ok(record) => record.fields.into_iter().nth(field as usize),
                    Err(shared) => shared.fields.get(field as usize).cloned(),
                }
                .unwrap_or(Value::Absent);
                self.push(value);
            }
            Instr::Index(n) => {
                let indices = self.pop_indices(n)?;
                let Value::Array(array) = self.pop() else { return Err(self.error(Err::ArgValue, "not an array")) };
                let flat = storage::element_index(array.dims, &indices).map_err(|f| self.fault(f))?;
                let value = array.elems.into_iter().nth(flat as usize).unwrap_or(Value::Absent);
                self.push(value);
            }
            Instr::Unary(op) => {
                let value = self.pop();
                let res = ops::unary(op, value, self.types).map_err(|f| self.fault(f))?;
                self.push(res);
            }
            Instr::Binary(op) => {
                let rhs = self.pop();
                let lhs = self.pop();
                let res = ops::binary(op, lhs, rhs, self.types).map_err(|f| self.fault(f))?;
                self.push(res);
            }
            Instr::BinOp { op, lhs, rhs } => {
                let rhs = self.operand(&code, base, rhs)?;
                let lhs = self.operand(&code, base, lhs)?;
                let res = ops::binary(op, lhs, rhs, self.types).map_err(|f| self.fault(f))?;
                self.push(res);
            }
            Instr::MakeRecord(ty, n) => instr::make_record(&mut self.storage.stack, ty, n),
            Instr::MakeArray(n) => {
                let at = self.storage.stack.len() - n as usize;
                let elems = self.storage.stack.split_off(at);
                let array = Array { dims: [n, 0, 0], elems };
                self.push(crate::compile::flatten_array(array));
            }
            Instr::Jump(target) => next = target,
            Instr::JumpIfFalse(target) => match self.pop() {
                Value::Bool(false) => next = target,
                Value::Bool(true) => {}
                _ => return Err(self.error(Err::ArgValue, "a condition did not give a bool")),
            },
            Instr::Pop => {
                self.pop();
            }
            Instr::Call(site) => return self.call(&code, site, host),
            Instr::LateCall(site) => return self.late_call(&code, site),
            Instr::UnknownFunc(name) => {
                let name = match code.consts.get(name as usize) {
                    Some(Value::Str(text)) => text.to_string(),
                    _ => "?".to_owned(),
                };
                return Err(self.error(Err::RefUnknownFunc, format!("no function `{name}` is loaded")));
            }
            Instr::Return => return Ok(self.return_from(None)),
            Instr::ReturnValue => {
                let value = self.pop();
                return Ok(self.return_from(Some(value)));
            }
            Instr::Raise => {
                let n = self.pop_num()?;
                if self.raise_ignored_in_undo() {
                    self.frame_mut().pc = next;
                    return Ok(None);
                }
                let error = self.user_error(n);
                // In an ERROR handler, RAISE hands the (new) error to the caller's
                // handler (§1.12); elsewhere it is raised here.
                if self.frame().active.is_some() {
                    if let Some(active) = self.frame_mut().active.as_mut() {
                        active.error = error.clone();
                    }
                    return self.re_raise();
                }
                return Err(error);
            }
            Instr::ReRaise => return self.re_raise(),
            Instr::Retry => return self.retry(),
            Instr::TryNext => {
                let active = self.frame_mut().active.take();
                let Some(active) = active else { return Err(RapidError::fatal("TRYNEXT outside an ERROR handler")) };
                next = active.stmt.end;
                self.frame_mut().retries = 0;
            }
            Instr::Exit => return Ok(self.exit_instruction()),
            Instr::UndoReturn => self.undo_return(),
            Instr::ForInit { var, has_step } => {
                let step = if has_step { Some(self.pop_num()?) } else { None };
                let to = self.pop_num()?;
                let from = self.pop_num()?;
                // Without STEP the loop counts up by 1, or down by 1 when FROM > TO.
                let step = step.unwrap_or(if from > to { -1.0 } else { 1.0 });
                let slots = (base + var) as usize;
                self.storage.stack[slots] = Value::Num(from as f32);
                self.storage.stack[slots + 1] = Value::Num(to as f32);
                self.storage.stack[slots + 2] = Value::Num(step as f32);
            }
            Instr::ForCheck { var, exit } => {
                let slots = (base + var) as usize;
                let (v, to, step) = (
                    self.storage.stack[slots].as_f64().unwrap_or(0.0),
                    self.storage.stack[slots + 1].as_f64().unwrap_or(0.0),
                    self.storage.stack[slots + 2].as_f64().unwrap_or(0.0),
                );
                if instr::for_passed(v, to, step) {
                    next = exit;
                }
            }
            Instr::ForNext { var, check } => {
                let slots = (base + var) as usize;
                // The loop variable and STEP are nums (`ForInit` made them): f32 sums,
                // as the fast loop's (an f64 sum rounded to f32 is the same number).
                let v = self.storage.stack[slots].as_f64().unwrap_or(0.0) as f32;
                let step = self.storage.stack[slots + 2].as_f64().unwrap_or(0.0) as f32;
                self.storage.stack[slots] = Value::Num(instr::for_next(v, step));
                next = check;
            }
            Instr::Present(slot) => {
                let present = !self.storage.stack[(base + slot) as usize].is_absent();
                self.push(Value::Bool(present));
            }
            Instr::Placeholder => return Err(self.error(Err::ExecPlaceholder, "a placeholder cannot be executed")),
            Instr::PushTime => self.push(Value::Dnum(self.time)),
            Instr::WaitPop => {
                let seconds = self.pop_num()?;
                self.frame_mut().pc = next;
                // WaitUntil polls every 100 ms (§1.20): it is not resumed early.
                self.wait_rechecks = false;
                return Ok(Some(Exit::Wait(seconds.max(0.0))));
            }
            Instr::Connect(trap) => {
                let Value::Ref(place) = self.pop() else { return Err(RapidError::fatal("CONNECT without an intnum")) };
                let current = self.storage.get(&place).ok().and_then(Value::as_f64).unwrap_or(0.0);
                if current >= 1.0 && self.resources.interrupts.get_mut(current as u32).is_some() {
                    return Err(self.error(Err::AlreadyConnected, "the intnum is connected to a trap already"));
                }
                let number = self.resources.interrupts.connect(trap);
                self.storage.set(&place, Value::Num(number as f32)).map_err(|f| self.fault(f))?;
            }
            Instr::ReadSignal(name) => {
                let data = self.pop();
                let value = self.read_signal(&data);
                match value {
                    Ok(value) => self.push(Value::Num(value as f32)),
                    // The signal's I/O device is disabled (manual §1.9).
                    Err(Some(message)) => return Err(self.error(Err::NoRunUnit, message)),
                    Err(None) => {
                        let name = match code.consts.get(name as usize) {
                            Some(Value::Str(s)) => s.to_string(),
                            _ => String::new(),
                        };
                        return Err(self.error(
                            Err::NoAliasIoDef,
                            format!("the signal variable `{name}` is not connected to an I/O signal (AliasIO)"),
                        ));
                    }
                }
            }
            Instr::RaiseWaitTimeout => {
                return Err(
                    self.error(Err::WaitMaxTime, "WaitUntil: the condition did not become TRUE within \\MaxTime")
                )
            }
            Instr::NameWithNumber => {
                let number = self.pop_num()?;
                let name = match self.pop() {
                    Value::Str(s) => s,
                    _ => return Err(self.error(Err::CallProc, "CallByVar needs a name")),
                };
                self.push(Value::Str(format!("{name}{}", number as i64).into()));
            }
            Instr::FellOffEnd => return self.fell_off_end(),
        }
        self.frame_mut().pc = next;
        Ok(None)
    }

    fn pop_indices(&mut self, n: u8) -> Result<Vec<f64>, RapidError> {
        let mut indices = vec![0.0; n as usize];
        for slot in indices.iter_mut().rev() {
            *slot = self.pop_num()?;
        }
        Ok(indices)
    }

    fn operand(&mut self, code: &Code, base: u32, operand: crate::ir::Operand) -> Result<Value, RapidError> {
        match operand {
            crate::ir::Operand::Stack => Ok(self.pop()),
            crate::ir::Operand::Local(slot) => self.load_local(base + slot),
            crate::ir::Operand::Const(i) => Ok(code.consts[i as usize].clone()),
        }
    }

    fn pop_index_array(&mut self, n: u8) -> Result<[f64; 3], RapidError> {
        let mut indices = [0.0; 3];
        for slot in indices.iter_mut().take(n as usize).rev() {
            *slot = self.pop_num()?;
        }
        Ok(indices)
    }

    /// The root place of an array named directly (a local slot through its reference).
    fn array_root(&self, global: bool, stack_index: u32, slot: u32) -> Result<Place, RapidError> {
        if global {
            return Ok(Place { root: Root::Global(slot), path: Vec::new() });
        }
        match &self.storage.stack[stack_index as usize] {
            Value::Ref(place) => Ok((**place).clone()),
            Value::Absent => Err(self.error(Err::NotPresent, "an optional parameter was not passed")),
            _ => Ok(Place { root: Root::Stack(stack_index), path: Vec::new() }),
        }
    }

    fn element(&self, global: bool, stack_index: u32, slot: u32, indices: &[f64]) -> Result<&Value, RapidError> {
        let array = if global {
            self.storage.globals.get(slot)
        } else {
            match &self.storage.stack[stack_index as usize] {
                Value::Ref(place) => Some(self.storage.get(place).map_err(|f| self.fault(f))?),
                value => Some(value),
            }
        };
        let Some(Value::Array(array)) = array else { return Err(self.error(Err::ArgValue, "not an array")) };
        let flat = storage::element_index(array.dims, indices).map_err(|f| self.fault(f))?;
        Ok(&array.elems[flat as usize])
    }

    fn element_place(&self, global: bool, stack_index: u32, slot: u32, indices: &[f64]) -> Result<Place, RapidError> {
        let root = self.array_root(global, stack_index, slot)?;
        index_place(&self.storage, root, indices).map_err(|f| self.fault(f))
    }

    fn load_local(&self, index: u32) -> Result<Value, RapidError> {
        match &self.storage.stack[index as usize] {
            Value::Ref(place) => self.storage.get(place).cloned().map_err(|f| self.fault(f)),
            Value::Absent => Err(self.error(Err::NotPresent, "an optional parameter was not passed")),
            value => Ok(value.clone()),
        }
    }

    fn store_local(&mut self, index: u32, value: Value) -> Result<(), RapidError> {
        let slot = &mut self.storage.stack[index as usize];
        if let Value::Ref(_) = slot {
            // Take the reference out while storing through it (no copy of the place).
            let reference = std::mem::replace(slot, Value::Absent);
            let res = match &reference {
                Value::Ref(place) => self.storage.set(place, value),
                _ => Ok(()),
            };
            self.storage.stack[index as usize] = reference;
            return res.map_err(|f| self.fault(f));
        }
        match coerce_like(slot, value) {
            Ok(value) => {
                *slot = value;
                Ok(())
            }
            Err(fault) => Err(self.fault(fault)),
        }
    }

    /// Builds a built-in's context, runs it, and returns the wait/stop it asked for.
    fn run_builtin(
        &mut self,
        id: crate::builtins::BuiltinId,
        args: &[Value],
        host: &mut dyn crate::host::Host,
    ) -> Result<(Option<Value>, Option<f64>, crate::builtins::StopKind), RapidError> {
        let mut ctx = Ctx {
            storage: &mut self.storage,
            host,
            types: self.types,
            time: self.time,
            wait: None,
            waited: 0.0,
            stop: crate::builtins::StopKind::None,
            errnos: &self.errnos,
            pers_globals: &self.pers_globals,
            retries_left: MAX_RETRIES.saturating_sub(self.frames.last().map_or(0, |f| f.retries)),
            reset_retries: false,
            skip_warn: false,
            next_booked: &mut self.next_booked,
            events: &mut self.events,
            data_by_name: &self.data_by_name,
            procs_by_name: &self.procs_by_name,
            routines: &self.routines,
            routine: self.frames.last().map_or("", |f| f.code.name.as_str()),
            wall_epoch: self.wall_epoch,
            resources: &mut self.resources,
            chain: &self.frames,
            builtins: &self.builtins,
        };
        let first_event = ctx.events.next_seq();
        let res = self.builtins.function(id)(&mut ctx, args);
        let waited = ctx.waited;
        let (wait, stop, reset, skip_warn) = (ctx.wait, ctx.stop, ctx.reset_retries, ctx.skip_warn);
        self.time += waited;
        // What the built-in logged (ErrWrite, ErrLog, ErrRaise) happened at its call.
        if self.events.next_seq() != first_event {
            if let Some(frame) = self.frames.last() {
                self.events.place_since(first_event, &Self::place_of(frame));
            }
        }
        self.after_builtin_hooks();
        let res = res?;
        if reset {
            if let Some(frame) = self.frames.last_mut() {
                frame.retries = 0;
            }
        }
        if skip_warn {
            self.drop_handled_warning();
        }
        if let Some(request) = self.resources.modules.take_request() {
            self.module_request(request, host)?;
        }
        Ok((res, wait, stop))
    }
}
