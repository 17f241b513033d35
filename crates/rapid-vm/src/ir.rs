//! The compiled form of a routine: a stack machine's instructions over numbered
//! slots (never names), a constant pool, call-site descriptions and the statement
//! table that error recovery (RETRY, TRYNEXT) works from.

use rapid_sema::types::TypeId;
use rapid_syntax::ast::{BinaryOp, UnaryOp};
use rapid_syntax::Span;

use crate::builtins::BuiltinId;
use crate::instrs::*;
use crate::value::Value;

crate::instrs::for_each_instr!(define_ops[
    /// One instruction. Operands come from and results go to the frame's operand
    /// stack. Declared in `crate::instrs` (one line each: operands, doc, facts).
    /// `repr(u8)`: a plain tag byte, so the fast loop's dispatch reads it without
    /// decoding a niche (two instructions fewer on every instruction executed).
    #[derive(Debug, Clone, Copy, PartialEq)]
    #[repr(u8)]
    pub enum Instr
]);

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

crate::instrs::for_each_kernel_op!(define_ops[
    /// One operation of a kernel, declared in `crate::instrs`.
    #[derive(Debug, Clone, Copy, PartialEq)]
    pub enum KernelOp
]);

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
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
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

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Callee {
    Routine(u32),
    Builtin(BuiltinId),
    /// Late binding: resolved by name at run time.
    Late,
}

/// What a call passes and to whom. Identical sites of a routine are one entry (a CAM
/// module's moves share a handful), so the table grows with the kinds of calls, not
/// with the calls.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
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
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum ArgOrigin {
    /// The whole data object the argument names (also for an element or component).
    Data(std::rc::Rc<str>),
    /// The calling routine's parameter `n`: its own argument is the origin.
    Param(u32),
    /// An expression, an absent optional argument or a switch: no data object.
    None,
}

/// A late-bound call's argument, as written: matched to the callee's parameters
/// by position or name only when the call runs (the callee is not known before).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct LateArg {
    /// The value pushed is a place (the argument is data), so a VAR, INOUT or PERS
    /// parameter can take it.
    pub by_ref: bool,
    /// The parameter name written (`a := x`, `\Opt := x`, `\Switch`), lowercased.
    pub name: Option<Box<str>>,
    /// Written with `\`: it goes to an optional parameter.
    pub optional: bool,
    pub kind: LateArgKind,
}

/// What a late-bound call's argument passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LateArgKind {
    /// A value (or place) the caller pushed.
    Pushed,
    /// `\Name` without a value: a switch.
    Switch,
    /// `\Name ? param`: the caller's optional parameter in local slot `slot`.
    Conditional(u32),
}

/// What a late-bound call needs to know of a parameter to match arguments to it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParamMeta {
    /// The name, lowercased.
    pub name: Box<str>,
    pub optional: bool,
    pub switch: bool,
    /// Parameters with the same group are alternatives (`\A | \B`).
    pub group: u16,
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
    /// Constant aggregates, packed (`Instr::Aggregate`).
    pub aggregates: crate::packed::Pool,
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
    /// For each parameter: its name, optional or switch, its group (late binding).
    pub param_meta: Vec<ParamMeta>,
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
    /// The local slots of the routine's CONST data (a debugger may not write them).
    pub const_locals: Vec<u32>,
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

    /// Gives back what the tables hold beyond their contents: they grew by doubling
    /// while the routine was compiled, and a CAM routine's are megabytes.
    pub fn shrink_to_fit(&mut self) {
        self.instrs.shrink_to_fit();
        self.consts.shrink_to_fit();
        self.aggregates.shrink_to_fit();
        self.sites.shrink_to_fit();
        self.stmts.shrink_to_fit();
        self.arg_origins.shrink_to_fit();
        self.kernels.shrink_to_fit();
    }

    pub fn constant(&mut self, value: Value) -> u32 {
        self.consts.push(value);
        self.consts.len() as u32 - 1
    }
}
