//! The implementations of built-in instructions and functions, one file per family.
//! Their signatures are declared once in rapid-lib's catalogue; this table maps a
//! built-in's name to the Rust function that runs it. A built-in missing here is
//! refused by the compiler with "not supported by `rapid run` yet".

mod argname;
mod bits;
mod calendar;
pub mod cfgdata;
mod clock;
pub mod controller;
mod dialogs;
mod dnheader;
mod events;
pub mod files;
mod geometry;
pub mod interrupts;
pub mod io;
pub mod io_config;
mod io_units;
mod io_wait;
mod math;
mod matrix;
pub mod modules;
pub mod motion;
mod pendant;
pub mod pure;
mod random;
mod rawbytes;
pub mod rmq;
pub mod sockets;
pub mod spy;
mod strdig;
mod strformat;
mod strings;
mod symbols;
pub use strings::{read_literal, value_literal};
pub use symbols::same_type;
pub mod symsearch;
pub(crate) mod syncmove;
mod sysinfo;
mod system;
pub mod tasking;
pub mod texttab;

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
    /// Wall-clock seconds since 1970 when the program was loaded (CDate, CTime).
    pub wall_epoch: f64,
    /// Open files, directories and sockets of the task.
    pub resources: &'a mut Resources,
    /// The call chain, outermost first; the last frame made the call (ExecHandler,
    /// ExecLevel).
    pub(crate) chain: &'a [crate::exec::Frame],
}

/// What the task holds open outside the interpreter: each family keeps its own table,
/// referred to by `OpaqueState::Handle` in the program's iodev/dir/socketdev data.
#[derive(Default)]
pub struct Resources {
    pub files: files::FileState,
    pub sockets: sockets::SocketState,
    /// Installed user text tables (kept at PP to Main, as the controller keeps them).
    pub texttab: texttab::TextTabState,
    /// The task's module data by module, and the search SetDataSearch started.
    pub symsearch: symsearch::SymSearchState,
    /// The execution log SpyStart opened (ended at PP to Main, as on the controller).
    pub spy: spy::SpyState,
    pub modules: modules::ModuleState,
    /// Rand's generator (kept across PP to Main: the sequence goes on).
    pub random: random::RandomState,
    /// The task's I/O system (signals) and the RAPID types of the signal kinds.
    pub io: io::IoState,
    /// The task's interrupts (deleted at PP to Main).
    pub interrupts: interrupts::InterruptState,
    /// The system parameters the run was started with (kept at PP to Main).
    pub cfgdata: cfgdata::CfgState,
    /// Which task this is and what the tasks share (sync points).
    pub tasking: tasking::TaskingState,
    /// The motion settings (reset to their defaults at PP to Main).
    pub motion: motion::MotionState,
    /// The task's side of the RAPID Message Queue.
    pub rmq: rmq::RmqState,
    /// The task's robot: its model, its planned motion, where it is.
    pub robot: motion::robot::RobotState,
    /// The operating mode, speed override and PP flags (kept at PP to Main).
    pub controller: controller::ControllerState,
}

/// What the tasks of one controller share: handed to the task that runs, so each
/// task's built-ins see the one I/O system and the one set of sync points.
#[derive(Default)]
pub struct Shared {
    pub io: io::SharedIo,
    pub tasking: tasking::SharedTasking,
}

impl Resources {
    /// Closes every file, directory and socket (end of program, PP to Main: the
    /// start-up table of §1.2.2 closes files and sockets).
    pub fn close_all(&mut self) {
        self.files.close_all();
        self.sockets.close_all();
        self.symsearch.end_search();
        self.spy.stop();
        self.modules.close_all();
        self.interrupts.clear();
        self.tasking.end_waits();
        self.rmq.end_waits();
        self.motion.reset();
    }

    /// Swaps the controller's shared state with the task's (hand in, take back).
    pub fn exchange_shared(&mut self, shared: &mut Shared) {
        self.io.exchange_shared(&mut shared.io);
        std::mem::swap(&mut self.tasking.shared, &mut shared.tasking);
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

/// Present means passed: not absent.
pub fn present(arg: Option<&Value>) -> bool {
    arg.is_some_and(|a| !a.is_absent())
}

/// One family's built-ins: (name as the catalogue spells it, implementation).
pub type Entries = &'static [(&'static str, BuiltinFn)];

/// Every family's table; a built-in's id is its position in their concatenation.
static FAMILIES: &[Entries] = &[
    CORE,
    files::ENTRIES,
    sockets::ENTRIES,
    matrix::ENTRIES,
    sysinfo::ENTRIES,
    strdig::ENTRIES,
    strformat::ENTRIES,
    argname::ENTRIES,
    texttab::ENTRIES,
    symsearch::ENTRIES,
    dnheader::ENTRIES,
    modules::ENTRIES,
    random::ENTRIES,
    io::ENTRIES,
    interrupts::ENTRIES,
    io_wait::ENTRIES,
    io_units::ENTRIES,
    spy::ENTRIES,
    cfgdata::ENTRIES,
    tasking::ENTRIES,
    syncmove::ENTRIES,
    motion::ENTRIES,
    rmq::ENTRIES,
    controller::ENTRIES,
];

static TABLE: std::sync::LazyLock<Vec<(&'static str, BuiltinFn)>> =
    std::sync::LazyLock::new(|| FAMILIES.iter().flat_map(|family| family.iter().copied()).collect());

/// The built-ins implemented before the library was split into families.
static CORE: Entries = &[
    ("TPWrite", pendant::tp_write),
    ("TPErase", pendant::tp_erase),
    ("TPShow", pendant::tp_show),
    ("ClearRawBytes", rawbytes::clear_raw_bytes),
    ("CopyRawBytes", rawbytes::copy_raw_bytes),
    ("PackRawBytes", rawbytes::pack_raw_bytes),
    ("UnpackRawBytes", rawbytes::unpack_raw_bytes),
    ("RawBytesLen", rawbytes::raw_bytes_len),
    ("ErrWrite", pendant::err_write),
    ("TPReadNum", dialogs::tp_read_num),
    ("TPReadDnum", dialogs::tp_read_num),
    ("TPReadFK", dialogs::tp_read_fk),
    ("UINumEntry", dialogs::ui_num_entry),
    ("UIDnumEntry", dialogs::ui_dnum_entry),
    ("UIAlphaEntry", dialogs::ui_alpha_entry),
    ("UIClientExist", dialogs::ui_client_exist),
    ("UIMsgBox", dialogs::ui_msg_box),
    ("UIMessageBox", dialogs::ui_message_box),
    ("UIListView", dialogs::ui_list_view),
    ("UINumTune", dialogs::ui_num_tune),
    ("UIDnumTune", dialogs::ui_dnum_tune),
    ("RemainingRetries", system::remaining_retries),
    ("ResetRetryCount", system::reset_retry_count),
    ("SkipWarn", system::skip_warn),
    ("ErrLog", events::err_log),
    ("ErrRaise", events::err_raise),
    ("WaitTime", system::wait_time),
    ("ClkReset", clock::clk_reset),
    ("ClkStart", clock::clk_start),
    ("ClkStop", clock::clk_stop),
    ("ClkRead", clock::clk_read),
    ("Stop", system::stop),
    ("ExitCycle", system::exit_cycle),
    ("Break", system::break_),
    ("BookErrNo", system::book_err_no),
    ("Dim", system::dim),
    ("IsPers", system::is_pers),
    ("IsVar", system::is_var),
    ("Max", math::max),
    ("Min", math::min),
    ("StrOrder", strings::str_order),
    ("StrToVal", strings::str_to_val),
    ("Abs", math::abs),
    ("AbsDnum", math::abs),
    ("Sqrt", math::sqrt),
    ("SqrtDnum", math::sqrt),
    ("Pow", math::pow),
    ("PowDnum", math::pow),
    ("Exp", math::exp),
    ("Round", math::round),
    ("RoundDnum", math::round),
    ("Trunc", math::trunc),
    ("TruncDnum", math::trunc),
    ("Sin", math::sin),
    ("Cos", math::cos),
    ("Tan", math::tan),
    ("ASin", math::asin),
    ("ACos", math::acos),
    ("ATan", math::atan),
    ("ATan2", math::atan2),
    ("SinDnum", math::sin_dnum),
    ("CosDnum", math::cos_dnum),
    ("TanDnum", math::tan_dnum),
    ("ASinDnum", math::asin_dnum),
    ("ACosDnum", math::acos_dnum),
    ("ATanDnum", math::atan_dnum),
    ("ATan2Dnum", math::atan2_dnum),
    ("TryInt", math::try_int),
    ("CDate", calendar::c_date),
    ("CTime", calendar::c_time),
    ("GetTime", calendar::get_time),
    ("ExecHandler", system::exec_handler),
    ("ExecLevel", system::exec_level),
    ("GetDataVal", symbols::get_data_val),
    ("SetDataVal", symbols::set_data_val),
    ("Incr", math::incr),
    ("Decr", math::decr),
    ("Add", math::add),
    ("Clear", math::clear),
    ("DotProd", math::dot_prod),
    ("CrossProd", math::cross_prod),
    ("VectMagn", math::vect_magn),
    ("OrientZYX", geometry::orient_zyx),
    ("EulerZYX", geometry::euler_zyx),
    ("NOrient", geometry::n_orient),
    ("PoseMult", geometry::pose_mult),
    ("PoseInv", geometry::pose_inv),
    ("PoseVect", geometry::pose_vect),
    ("NumToDnum", math::num_to_dnum),
    ("DnumToNum", math::dnum_to_num),
    ("StrLen", strings::str_len),
    ("StrPart", strings::str_part),
    ("StrFind", strings::str_find),
    ("StrMatch", strings::str_match),
    ("StrMemb", strings::str_memb),
    ("StrMap", strings::str_map),
    ("NumToStr", strings::num_to_str),
    ("DnumToStr", strings::dnum_to_str),
    ("ValToStr", strings::val_to_str),
    ("BitAnd", bits::bit_and),
    ("BitOr", bits::bit_or),
    ("BitXOr", bits::bit_xor),
    ("BitNeg", bits::bit_neg),
    ("BitLSh", bits::bit_lsh),
    ("BitRSh", bits::bit_rsh),
    ("BitCheck", bits::bit_check),
    ("BitSet", bits::bit_set),
    ("BitClear", bits::bit_clear),
    ("BitAndDnum", bits::bit_and_dnum),
    ("BitOrDnum", bits::bit_or_dnum),
    ("BitXOrDnum", bits::bit_xor_dnum),
    ("BitNegDnum", bits::bit_neg_dnum),
    ("BitLShDnum", bits::bit_lsh_dnum),
    ("BitRShDnum", bits::bit_rsh_dnum),
    ("BitCheckDnum", bits::bit_check_dnum),
    ("ByteToStr", bits::byte_to_str),
    ("StrToByte", bits::str_to_byte),
    ("DecToHex", bits::dec_to_hex),
    ("HexToDec", bits::hex_to_dec),
];

/// The implementation of the built-in named `name` (any letter case).
pub fn lookup(name: &str) -> Option<BuiltinId> {
    TABLE.iter().position(|(n, _)| n.eq_ignore_ascii_case(name)).map(|i| BuiltinId(i as u16))
}

/// Built-ins the compiler turns into instructions of their own instead of a call
/// (see `compile/call.rs`): they run although they are in no family's table.
const COMPILED_INLINE: &[&str] = &["Present", "CallByVar", "Type", "WaitUntil"];

/// Whether `rapid run` runs the built-in named `name` (any letter case); a program
/// calling one that is not is refused when it is loaded.
pub fn implemented(name: &str) -> bool {
    lookup(name).is_some() || COMPILED_INLINE.iter().any(|n| n.eq_ignore_ascii_case(name))
}

pub fn function(id: BuiltinId) -> BuiltinFn {
    TABLE[id.0 as usize].1
}

pub fn name(id: BuiltinId) -> &'static str {
    TABLE[id.0 as usize].0
}
