//! The compiled form of a routine: a stack machine's instructions over numbered
//! slots (never names), a constant pool, call-site descriptions and the statement
//! table that error recovery (RETRY, TRYNEXT) works from.

use rapid_sema::types::TypeId;
use rapid_syntax::ast::{BinaryOp, UnaryOp};
use rapid_syntax::Span;

use crate::builtins::BuiltinId;
use crate::value::Value;

/// One instruction. Operands come from and results go to the frame's operand stack.
/// `repr(u8)`: a plain tag byte, so the fast loop's dispatch reads it without
/// decoding a niche (two instructions fewer on every instruction executed).
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(u8)]
pub enum Instr {
    /// Push constant `n` of the pool.
    Const(u32),
    /// Push the value of local slot `n` (through it when it holds a reference).
    LoadLocal(u32),
    /// Pop a value into local slot `n` (through it when it holds a reference).
    StoreLocal(u32),
    LoadGlobal(u32),
    StoreGlobal(u32),
    /// Push the place of local slot `n` (the referenced place for a reference).
    PlaceLocal(u32),
    PlaceGlobal(u32),
    /// Replace the place on top with its component `n`.
    PlaceField(u16),
    /// Pop `n` indices and a place; push the element's place (bounds checked).
    PlaceIndex(u8),
    /// Pop a place, push its value.
    LoadPlace,
    /// Pop a value and a place; store the value there.
    StorePlace,
    /// Pop `n` indices; push that element of the array in local slot `slot` (through
    /// a reference) or global `slot`.
    LoadElem {
        global: bool,
        slot: u32,
        n: u8,
    },
    /// Pop a value and `n` indices; store the value in that element.
    StoreElem {
        global: bool,
        slot: u32,
        n: u8,
    },
    /// Pop a record, push its component `n`.
    Field(u16),
    /// Pop `n` indices and an array, push the element.
    Index(u8),
    Unary(UnaryOp),
    Binary(BinaryOp),
    /// A binary operator whose operands may come straight from a local slot or the
    /// constant pool instead of the stack (the right one popped first).
    BinOp {
        op: BinaryOp,
        lhs: Operand,
        rhs: Operand,
    },
    /// Pop `n` values, push a record of type `ty`.
    MakeRecord(TypeId, u16),
    /// Pop `n` values (elements or rows), push an array.
    MakeArray(u32),
    Jump(u32),
    /// Pop a bool; jump when it is FALSE.
    JumpIfFalse(u32),
    Pop,
    /// Call routine or built-in described by call site `n`.
    Call(u32),
    /// Pop a string naming a procedure; call it with call site `n`'s arguments.
    LateCall(u32),
    /// A call of a function defined nowhere in the task: raise ERR_REFUNKFUN (constant
    /// `n` names it). The controller links late, so only executing it fails.
    UnknownFunc(u32),
    /// End a PROC or TRAP.
    Return,
    /// Pop the value a FUNC returns.
    ReturnValue,
    /// Pop an error number and raise it.
    Raise,
    /// Raise the current error again in the caller (bare RAISE in an ERROR handler).
    ReRaise,
    Retry,
    TryNext,
    Exit,
    /// A RETURN written in an UNDO handler: ignored, with an event-log warning
    /// (manual §1.13; `exec/undo.rs`).
    UndoReturn,
    /// FOR: pop FROM, TO and STEP (or none for the default) into slots var, var+1, var+2.
    ForInit {
        var: u32,
        has_step: bool,
    },
    /// FOR: jump to `exit` when the loop variable has passed TO.
    ForCheck {
        var: u32,
        exit: u32,
    },
    /// FOR: add STEP to the variable and jump back to `check`.
    ForNext {
        var: u32,
        check: u32,
    },
    /// Push whether optional parameter slot `n` was passed.
    Present(u32),
    /// Executing a placeholder raises ERR_EXECPHR.
    Placeholder,
    /// Pop a number and a name; push the name followed by the number (CallByVar).
    NameWithNumber,
    /// Push the controller's time in seconds (a dnum).
    PushTime,
    /// Pop a number of seconds and wait that long (the run hands control back).
    WaitPop,
    /// Raise the predefined error `0` (WaitUntil's timeout).
    RaiseWaitTimeout,
    /// CONNECT: pop the intnum's place; give it a new interrupt whose trap is routine `n`
    /// (ERR_ALRDYCNT when it is connected already).
    Connect(u32),
    /// Pop signal data, push the signal's value; data no AliasIO connected raises
    /// ERR_NO_ALIASIO_DEF (manual §1.9). Constant `n` names the data (for the message).
    ReadSignal(u32),
    /// The routine ran off its end without RETURN (in a FUNC: ERR_FNCNORET).
    FellOffEnd,
    /// Evaluate kernel `kernel` and store its result at its target, then continue at
    /// `skip`. When the kernel cannot run (an operand is not a plain num, or an error
    /// would arise) nothing happens and execution continues with the next instruction:
    /// the statement's general code, which follows and does it all again (a kernel only
    /// reads, so starting over is safe).
    KernelStore {
        kernel: u32,
        skip: u32,
    },
    /// `RETURN` of a num: evaluate kernel `kernel` and return its result from the FUNC;
    /// when the kernel or the plain return cannot run, the next instruction (the
    /// statement's general code).
    KernelReturn {
        kernel: u32,
    },
    /// Evaluate condition kernel `kernel`: FALSE jumps to `on_false`, TRUE continues at
    /// `skip`; when it cannot run, the next instruction (the condition's general code).
    KernelBranch {
        kernel: u32,
        on_false: u32,
        skip: u32,
    },
}

/// Most values a kernel holds at once (deeper expressions get no kernel).
pub const KERNEL_DEPTH: usize = 16;

/// A straight-line computation over nums (and the bools of comparisons) that the
/// executor evaluates in f32 registers, never touching the value stack. Compiled only
/// for expressions whose every leaf is num data or a num literal, so the result is the
/// one the general code would give whenever the kernel runs at all.
#[derive(Debug, Clone, PartialEq)]
pub struct Kernel {
    pub ops: Vec<KernelOp>,
    /// Where `KernelStore` puts the result (`None` for conditions).
    pub target: Option<KernelTarget>,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KernelOp {
    /// A num in local slot `n` (through a reference to a whole num).
    Local(u32),
    Global(u32),
    Const(f32),
    /// Pop an index; push that element of the one-dimensional num array in local or
    /// global `slot`.
    Elem {
        global: bool,
        slot: u32,
    },
    /// Push element `index + offset` of the one-dimensional num array in local or
    /// global `slot`, the index read from local slot `index`: `Local(index)`,
    /// `AddConst(offset)` (when not 0) and `Elem` fused at compile time, the commonest
    /// element reads (`a{j}`, `a{j + 1}`) in one dispatch instead of two or three.
    ElemAt {
        global: bool,
        slot: u32,
        index: u32,
        offset: f32,
    },
    /// Arithmetic and comparisons on nums; AND, OR, XOR on bools (1 or 0).
    Binary(BinaryOp),
    /// `Binary` whose right operand is read in place instead of pushed: the top
    /// becomes `top op operand` (a push followed by `Binary`, fused at compile time
    /// to halve the dispatches of typical expressions such as `acc * 7 + j`).
    BinaryWith(BinaryOp, KernelOperand),
    /// `BinaryWith` for the commonest operator and operand pairs, specialised at
    /// compile time so that the executor dispatches once, not three times (operation,
    /// operand kind, operator): `top + c`, `top - c`, `top * c`, `top MOD c`,
    /// `top + local`, `top < c`, `top > c`. Same results as `BinaryWith`.
    AddConst(f32),
    SubConst(f32),
    MulConst(f32),
    ModConst(f32),
    AddLocal(u32),
    LtConst(f32),
    GtConst(f32),
    Neg,
    Not,
}

/// The right operand of a fused kernel operation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KernelOperand {
    Local(u32),
    Global(u32),
    Const(f32),
}

/// Where a `KernelStore` writes. For `Elem` the kernel leaves two values: the index
/// (pushed first) and the value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KernelTarget {
    Local(u32),
    Global(u32),
    Elem { global: bool, slot: u32 },
}

/// Where an operand of `BinOp` comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Operand {
    Stack,
    Local(u32),
    Const(u32),
}

/// How a call passes each parameter, in parameter order.
#[derive(Debug, Clone, PartialEq)]
pub enum ArgSpec {
    /// A value computed by the caller (IN parameters).
    Value,
    /// A place computed by the caller (VAR, INOUT, PERS parameters).
    Place,
    /// Not passed.
    Absent,
    /// A switch that was passed.
    Switch,
    /// `\Name?param`: the caller's optional parameter in local slot `slot`, passed on
    /// only when present; `by_ref` for VAR/INOUT/PERS parameters.
    Conditional { slot: u32, by_ref: bool },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Callee {
    Routine(u32),
    Builtin(BuiltinId),
    /// Late binding: resolved by name at run time.
    Late,
}

#[derive(Debug, Clone, PartialEq)]
pub struct CallSite {
    pub callee: Callee,
    pub args: Vec<ArgSpec>,
    /// How many values the caller pushed (the Value and Place arguments).
    pub n_pushed: u16,
    /// Late binding: the arguments as written, matched against the callee at run time.
    pub late_args: Vec<LateArg>,
}

/// Where a call's argument came from, for ArgName: the data object it names, a
/// parameter of the calling routine (look one call further out), or nothing.
#[derive(Debug, Clone, PartialEq)]
pub enum ArgOrigin {
    /// The whole data object the argument names (also for an element or component).
    Data(std::rc::Rc<str>),
    /// The calling routine's parameter `n`: its own argument is the origin.
    Param(u32),
    /// An expression, an absent optional argument or a switch: no data object.
    None,
}

/// A late-bound call's argument: positional values only (places when the callee
/// wants references).
#[derive(Debug, Clone, PartialEq)]
pub struct LateArg {
    pub by_ref: bool,
}

/// A statement's code range, for RETRY (restart it) and TRYNEXT (go past it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StmtRange {
    pub start: u32,
    pub end: u32,
    pub span: Span,
    /// Nesting depth: 0 for the statements of a routine's body or handler.
    pub depth: u16,
    /// For a call of a user procedure: which routine (backward execution runs its
    /// BACKWARD handler).
    pub calls: Option<u32>,
}

/// One compiled routine.
#[derive(Debug, Clone, Default)]
pub struct Code {
    pub name: String,
    pub file: usize,
    pub instrs: Vec<Instr>,
    pub consts: Vec<Value>,
    pub sites: Vec<CallSite>,
    /// Local slots: parameters first, then routine data, loop variables, temporaries.
    pub n_locals: u32,
    pub n_params: u32,
    /// Default values of the non-parameter locals (slot n_params + i).
    pub local_defaults: Vec<Value>,
    /// Statements in order of their start; nested ones follow their parent.
    pub stmts: Vec<StmtRange>,
    pub error_handler: Option<Handler>,
    pub undo_handler: Option<u32>,
    pub backward_handler: Option<u32>,
    pub is_func: bool,
    pub is_trap: bool,
    pub span: Span,
    /// For each parameter: a value of its numeric kind when it is an IN num or dnum
    /// (arguments are converted to it), else `None`.
    pub param_likes: Vec<Option<Value>>,
    /// For each parameter: VAR, INOUT or PERS.
    pub param_by_ref: Vec<bool>,
    /// A FUNC's result is converted to the numeric kind of this value.
    pub ret_like: Option<Value>,
    /// The kernels of `KernelStore` and `KernelBranch`.
    pub kernels: Vec<Kernel>,
    /// For the call sites of user routines and of ArgName: where each argument came
    /// from, in parameter order (positional for late calls), sorted by site index.
    pub arg_origins: Vec<(u32, Box<[ArgOrigin]>)>,
    /// The names of the parameters and routine data with their local slots, as
    /// declared (a debugger shows a frame's locals by them; loop variables and
    /// temporaries have none).
    pub local_names: Vec<(String, u32)>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Handler {
    pub pc: u32,
    /// `ERROR (n1, n2)`: the errors it takes; empty takes all.
    pub numbers: Vec<i32>,
}

impl Code {
    /// The innermost statement whose code holds `pc`.
    pub fn stmt_at(&self, pc: u32) -> Option<StmtRange> {
        self.stmts.iter().rev().find(|s| s.start <= pc && pc < s.end).copied()
    }

    /// Where the arguments of call site `site` came from (ArgName), if recorded.
    pub fn arg_origins(&self, site: u32) -> Option<&[ArgOrigin]> {
        let at = self.arg_origins.binary_search_by_key(&site, |(s, _)| *s).ok()?;
        Some(&self.arg_origins[at].1)
    }

    pub fn emit(&mut self, instr: Instr) -> u32 {
        self.instrs.push(instr);
        self.instrs.len() as u32 - 1
    }

    pub fn here(&self) -> u32 {
        self.instrs.len() as u32
    }

    /// Points the jump at `at` to `target`.
    pub fn patch(&mut self, at: u32, target: u32) {
        match &mut self.instrs[at as usize] {
            Instr::Jump(t) | Instr::JumpIfFalse(t) => *t = target,
            Instr::ForCheck { exit, .. } => *exit = target,
            Instr::KernelBranch { on_false, .. } => *on_false = target,
            _ => {}
        }
    }

    /// Points the `skip` of the kernel instruction at `at` to `target`.
    pub fn patch_skip(&mut self, at: u32, target: u32) {
        if let Instr::KernelStore { skip, .. } | Instr::KernelBranch { skip, .. } = &mut self.instrs[at as usize] {
            *skip = target;
        }
    }

    pub fn constant(&mut self, value: Value) -> u32 {
        self.consts.push(value);
        self.consts.len() as u32 - 1
    }
}
