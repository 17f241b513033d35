//! Symbols and scopes (§1.1.5, §1.2.2): built-ins, task-global and module-local
//! declarations, routine data, parameters and FOR loop variables.

use std::rc::Rc;

use rapid_syntax::ast::{ParamMode, RoutineKind};
use rapid_syntax::{Span, Symbol};
use rustc_hash::FxHashMap;

use crate::types::TypeId;

/// Rank of an `anytype X{*}` parameter: any array.
pub const ANY_RANK: u8 = u8::MAX;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataKind {
    Var,
    Pers,
    Const,
    Param(ParamMode),
    LoopVar,
    /// A system variable programs may only read (ERRNO, INTNO).
    ReadOnly,
}

#[derive(Debug, Clone)]
pub struct DataInfo {
    pub display: String,
    pub ty: TypeId,
    pub rank: u8,
    /// Known sizes of the dimensions (0 = unknown).
    pub dims: [u32; 3],
    pub kind: DataKind,
    /// The value of a num CONST, when it is a constant expression we can evaluate.
    pub const_value: Option<f64>,
    /// An optional parameter of the routine being checked.
    pub optional: bool,
    /// Where the declaration is (to find its initial value).
    pub origin: DeclOrigin,
    /// Module-level data declared neither LOCAL nor TASK: a PERS of this kind is one
    /// object for every task of the system that declares it (§1.20).
    pub system_global: bool,
}

/// Where a data object or routine was declared.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DeclOrigin {
    /// Item `index` of the catalogue's module.
    Builtin(usize),
    /// Item `item` of user module `module` (index into the task's modules).
    Module { module: usize, item: usize },
    /// Routine data, a parameter or a loop variable.
    Routine,
}

impl DeclOrigin {
    /// Data the system configuration declares ([`crate::Options::predefined`]): a
    /// built-in that no catalogue item holds, so it starts with its type's default.
    pub const CONFIGURED: DeclOrigin = DeclOrigin::Builtin(usize::MAX);
}

#[derive(Debug, Clone)]
pub struct ParamInfo {
    pub name: Symbol,
    pub display: String,
    pub ty: TypeId,
    pub rank: u8,
    pub mode: ParamMode,
    pub optional: bool,
    pub group: u16,
}

impl ParamInfo {
    pub fn is_switch(&self) -> bool {
        self.ty == crate::types::SWITCH
    }
}

#[derive(Debug, Clone)]
pub struct RoutineInfo {
    pub display: String,
    pub kind: RoutineKind,
    pub ret: Option<TypeId>,
    pub params: Rc<[ParamInfo]>,
    /// Runs of mutually exclusive parameters, `(start, end)` indices into `params`.
    pub groups: Rc<[(usize, usize)]>,
    /// The catalogue chapter of a built-in (`None` for user routines).
    pub chapter: Option<&'static str>,
    /// How a built-in takes some of its arguments (its catalogue entry's flags; none
    /// for user routines).
    pub flags: rapid_lib::catalogue::RoutineFlags,
    /// The parameter list holds placeholders, so calls cannot be checked.
    pub has_placeholders: bool,
    /// Where the routine was declared.
    pub origin: DeclOrigin,
}

/// What a name denotes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Def {
    Data(u32),
    Routine(u32),
    Type(TypeId),
}

/// Where a module-level declaration came from, for duplicate checks.
#[derive(Debug, Clone, Copy)]
pub struct Origin {
    pub module: usize,
    pub span: Span,
    pub def: Def,
}

/// All declarations visible to a task, by scope level.
#[derive(Debug, Default)]
pub struct Scopes {
    pub builtins: FxHashMap<Symbol, Def>,
    pub globals: FxHashMap<Symbol, Origin>,
    pub module_locals: Vec<FxHashMap<Symbol, Def>>,
    /// Routine data and parameters of the routine being checked.
    pub routine: FxHashMap<Symbol, u32>,
    /// FOR loop variables, innermost last.
    pub loop_vars: Vec<(Symbol, u32)>,
}

impl Scopes {
    /// Resolves `sym` from inside module `module`: loop variables, routine data,
    /// module-local items, task-global items, then built-ins (§1.1.5, §1.2.2).
    pub fn lookup(&self, module: usize, sym: Symbol) -> Option<Def> {
        if let Some(&(_, data)) = self.loop_vars.iter().rev().find(|(s, _)| *s == sym) {
            return Some(Def::Data(data));
        }
        if let Some(&data) = self.routine.get(&sym) {
            return Some(Def::Data(data));
        }
        self.lookup_module_level(module, sym)
    }

    /// Like `lookup`, ignoring routine data (for declarations at module level).
    pub fn lookup_module_level(&self, module: usize, sym: Symbol) -> Option<Def> {
        if let Some(def) = self.module_locals.get(module).and_then(|m| m.get(&sym)) {
            return Some(*def);
        }
        if let Some(origin) = self.globals.get(&sym) {
            return Some(origin.def);
        }
        self.builtins.get(&sym).copied()
    }
}

/// Runs of consecutive parameters that share a group (mutually exclusive ones).
pub fn group_ranges(params: &[ParamInfo]) -> Rc<[(usize, usize)]> {
    let mut groups: Vec<(usize, usize)> = Vec::new();
    for (idx, param) in params.iter().enumerate() {
        match groups.last_mut() {
            Some(last) if params[last.0].group == param.group => last.1 = idx + 1,
            _ => groups.push((idx, idx + 1)),
        }
    }
    groups.into()
}
