//! Symbols and scopes (§1.1.5, §1.2.2): built-ins, task-global and module-local
//! declarations, routine data, parameters and FOR loop variables.

use std::rc::Rc;

use rapid_syntax::ast::{ParamMode, RoutineKind};
use rapid_syntax::{Span, Symbol};
use rustc_hash::FxHashMap;

use crate::types::TypeId;

/// Rank of an `anytype X{*}` parameter: any array.
pub(crate) const ANY_RANK: u8 = u8::MAX;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum DataKind {
    Var,
    Pers,
    Const,
    Param(ParamMode),
    LoopVar,
    /// A system variable programs may only read (ERRNO, INTNO).
    ReadOnly,
}

#[derive(Debug, Clone)]
pub(crate) struct DataInfo {
    pub(crate) display: String,
    pub(crate) ty: TypeId,
    pub(crate) rank: u8,
    /// Known sizes of the dimensions (0 = unknown).
    pub(crate) dims: [u32; 3],
    pub(crate) kind: DataKind,
    /// The value of a num CONST, when it is a constant expression we can evaluate.
    pub(crate) const_value: Option<f64>,
    /// An optional parameter of the routine being checked.
    pub(crate) optional: bool,
}

#[derive(Debug, Clone)]
pub(crate) struct ParamInfo {
    pub(crate) name: Symbol,
    pub(crate) display: String,
    pub(crate) ty: TypeId,
    pub(crate) rank: u8,
    pub(crate) mode: ParamMode,
    pub(crate) optional: bool,
    pub(crate) group: u16,
}

impl ParamInfo {
    pub(crate) fn is_switch(&self) -> bool {
        self.ty == crate::types::SWITCH
    }
}

#[derive(Debug, Clone)]
pub(crate) struct RoutineInfo {
    pub(crate) display: String,
    pub(crate) kind: RoutineKind,
    pub(crate) ret: Option<TypeId>,
    pub(crate) params: Rc<[ParamInfo]>,
    /// Runs of mutually exclusive parameters, `(start, end)` indices into `params`.
    pub(crate) groups: Rc<[(usize, usize)]>,
    /// The catalogue chapter of a built-in (`None` for user routines).
    pub(crate) chapter: Option<&'static str>,
    /// The parameter list holds placeholders, so calls cannot be checked.
    pub(crate) has_placeholders: bool,
}

/// What a name denotes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Def {
    Data(u32),
    Routine(u32),
    Type(TypeId),
}

/// Where a module-level declaration came from, for duplicate checks.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Origin {
    pub(crate) module: usize,
    pub(crate) span: Span,
    pub(crate) def: Def,
}

/// All declarations visible to a task, by scope level.
#[derive(Debug, Default)]
pub(crate) struct Scopes {
    pub(crate) builtins: FxHashMap<Symbol, Def>,
    pub(crate) globals: FxHashMap<Symbol, Origin>,
    pub(crate) module_locals: Vec<FxHashMap<Symbol, Def>>,
    /// Routine data and parameters of the routine being checked.
    pub(crate) routine: FxHashMap<Symbol, u32>,
    /// FOR loop variables, innermost last.
    pub(crate) loop_vars: Vec<(Symbol, u32)>,
}

impl Scopes {
    /// Resolves `sym` from inside module `module`: loop variables, routine data,
    /// module-local items, task-global items, then built-ins (§1.1.5, §1.2.2).
    pub(crate) fn lookup(&self, module: usize, sym: Symbol) -> Option<Def> {
        if let Some(&(_, data)) = self.loop_vars.iter().rev().find(|(s, _)| *s == sym) {
            return Some(Def::Data(data));
        }
        if let Some(&data) = self.routine.get(&sym) {
            return Some(Def::Data(data));
        }
        self.lookup_module_level(module, sym)
    }

    /// Like `lookup`, ignoring routine data (for declarations at module level).
    pub(crate) fn lookup_module_level(&self, module: usize, sym: Symbol) -> Option<Def> {
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
pub(crate) fn group_ranges(params: &[ParamInfo]) -> Rc<[(usize, usize)]> {
    let mut groups: Vec<(usize, usize)> = Vec::new();
    for (idx, param) in params.iter().enumerate() {
        match groups.last_mut() {
            Some(last) if params[last.0].group == param.group => last.1 = idx + 1,
            _ => groups.push((idx, idx + 1)),
        }
    }
    groups.into()
}
