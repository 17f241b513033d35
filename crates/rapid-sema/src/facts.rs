//! What the checker resolved in one top-level body item (or module data declaration),
//! for the compiler: the declaration each name and call denotes (and the routine a
//! statement names: a procedure call's, CONNECT's TRAP), the type of each expression,
//! the type a routine data declaration declares and the parameter each argument was
//! bound to. Kept by index into the item's arena and cleared with it, so it costs memory
//! per item, never per program; a [`crate::BodySink`] reads it beside the arena.

use rapid_syntax::ast::{ArgList, ExprId};

use crate::symbols::Def;
use crate::types::TypeId;

/// What a name (or the routine name of a call) denotes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Denotes {
    /// Nothing: an undefined function or procedure (a late error at run time).
    Nothing,
    /// A declaration of the task's tables: built-in or module-level data, a routine,
    /// a type.
    Decl(Def),
    /// The routine's own data: its parameters (placeholders left out), then its data
    /// declarations and FOR variables, numbered from 0 in the order they are declared.
    Local(u32),
}

/// The type the checker gave an expression.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExprType {
    /// A value of type `ty` with `rank` dimensions (0 for a scalar).
    Of { ty: TypeId, rank: u8 },
    /// A numeric literal, or arithmetic of numeric literals only (`2 * 0.1`, `-1`):
    /// numeric, typed by its context. RAPID accepts `VAR dnum d := 4294967295;`, a
    /// value no num holds exactly, so a literal takes the type of the data it is
    /// assigned to, of the other operand or of the parameter; `VAR dnum x := 2 * 0.1;`
    /// multiplies two dnums. The checker types such an expression num where nothing
    /// asks for a dnum, which is what it is *assignable* as, not how it is computed.
    Numeric,
}

/// An argument the checker saw but bound to no parameter.
const UNBOUND: u32 = u32::MAX;
/// An argument the checker did not see (its facts are not known).
const UNSEEN: u32 = u32::MAX - 1;

/// The facts of one body item (see the module doc).
#[derive(Debug, Default)]
pub struct ItemFacts {
    /// Whether facts are recorded (only when a sink takes them).
    pub(crate) recording: bool,
    /// By `ExprId`: what each `Name` and `Call` expression denotes.
    names: Vec<Option<Denotes>>,
    /// By `ExprId`: the type of each expression the checker typed without error.
    types: Vec<Option<ExprType>>,
    /// By index into the arena's arguments: the parameter each was bound to.
    params: Vec<u32>,
    /// Routines a statement names, by the start of their name: the routine a
    /// procedure call calls, the TRAP routine CONNECT connects.
    procedures: Vec<(u32, Denotes)>,
    /// The type of the data a declaration item declares, when the checker resolved it.
    declared: Option<TypeId>,
    /// The entries of `names` and `params` written for the item, reset when the next
    /// one starts. Items of a long body share one arena (the parser hands them over
    /// in batches), so resetting the whole table per item would cost the batch's size.
    written_names: Vec<u32>,
    written_types: Vec<u32>,
    written_params: Vec<u32>,
}

impl ItemFacts {
    /// What `Name` or `Call` expression `id` denotes, when the checker resolved it.
    pub fn name(&self, id: ExprId) -> Option<Denotes> {
        self.names.get(id.0 as usize).copied().flatten()
    }

    /// The type the checker gave expression `id`, when it typed it without error.
    pub fn ty(&self, id: ExprId) -> Option<ExprType> {
        self.types.get(id.0 as usize).copied().flatten()
    }

    /// The type of the data the item declares (routine data), when it is a
    /// declaration whose type the checker resolved.
    pub fn declared(&self) -> Option<TypeId> {
        self.declared
    }

    /// What the routine name starting at byte `name_start` of a statement denotes (a
    /// procedure call's callee, CONNECT's TRAP routine), when the checker resolved it.
    pub fn procedure(&self, name_start: u32) -> Option<Denotes> {
        let at = self.procedures.binary_search_by_key(&name_start, |&(start, _)| start).ok()?;
        Some(self.procedures[at].1)
    }

    /// The parameter each of `n_params` parameters gets from `args` (by index into
    /// the arena's arguments; the last one bound to a parameter wins, as
    /// `bind::bind_args` says), when the checker bound every argument of the call.
    pub fn bound(&self, args: ArgList, n_params: usize) -> Option<Vec<Option<u32>>> {
        let mut bound = vec![None; n_params];
        for arg in args.start..args.start + args.len {
            match *self.params.get(arg as usize)? {
                UNSEEN => return None,
                UNBOUND => {}
                param => *bound.get_mut(param as usize)? = Some(arg),
            }
        }
        Some(bound)
    }

    /// Starts the facts of an item whose arena holds `n_exprs` expressions and
    /// `n_args` arguments.
    pub(crate) fn start(&mut self, n_exprs: usize, n_args: usize) {
        for idx in self.written_names.drain(..) {
            self.names[idx as usize] = None;
        }
        for idx in self.written_types.drain(..) {
            self.types[idx as usize] = None;
        }
        for idx in self.written_params.drain(..) {
            self.params[idx as usize] = UNSEEN;
        }
        self.procedures.clear();
        self.declared = None;
        if self.recording {
            if self.names.len() < n_exprs {
                self.names.resize(n_exprs, None);
                self.types.resize(n_exprs, None);
            }
            if self.params.len() < n_args {
                self.params.resize(n_args, UNSEEN);
            }
        }
    }

    pub(crate) fn set_name(&mut self, id: ExprId, denotes: Denotes) {
        if let Some(slot) = self.names.get_mut(id.0 as usize) {
            *slot = Some(denotes);
            self.written_names.push(id.0);
        }
    }

    pub(crate) fn set_type(&mut self, id: ExprId, ty: Option<ExprType>) {
        if let Some(slot) = self.types.get_mut(id.0 as usize) {
            *slot = ty;
            self.written_types.push(id.0);
        }
    }

    /// Argument `arg` (an index into the arena's arguments) stands for parameter
    /// `param`, or for none.
    pub(crate) fn set_param(&mut self, arg: usize, param: Option<usize>) {
        if let Some(slot) = self.params.get_mut(arg) {
            *slot = param.map_or(UNBOUND, |p| p as u32);
            self.written_params.push(arg as u32);
        }
    }

    pub(crate) fn set_declared(&mut self, ty: TypeId) {
        if self.recording && ty != crate::types::ERROR {
            self.declared = Some(ty);
        }
    }

    pub(crate) fn set_procedure(&mut self, name_start: u32, denotes: Denotes) {
        if !self.recording {
            return;
        }
        // Statements are checked in source order, so the list stays sorted; a
        // statement checked twice keeps one entry.
        match self.procedures.binary_search_by_key(&name_start, |&(start, _)| start) {
            Ok(at) => self.procedures[at].1 = denotes,
            Err(at) => self.procedures.insert(at, (name_start, denotes)),
        }
    }
}
