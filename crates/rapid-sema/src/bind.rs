//! Which parameter each argument of a call stands for (§1.1.5 "过程调用", §1.3.4):
//! a named argument (`\Speed:=v`, `Value:=x`) its parameter, a positional one the next
//! required parameter group not given yet; a group of mutually exclusive parameters
//! (`num Value | dnum DValue`) takes the alternative whose type the argument has.
//!
//! One rule for the checker, which reports the arguments that fit nowhere, and for the
//! VM compiler, which binds the arguments of a checked program the same way. Each
//! caller says whether an argument fits an alternative from what it knows of the
//! argument's type ([`fits`] is the rule), asked only when alternatives are chosen from.

use rapid_syntax::ast::{Arg, ArgKind, ExprId};

use crate::symbols::{ParamInfo, RoutineInfo};
use crate::types::{TypeId, Types};

/// What one argument was bound to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Binding {
    /// The argument stands for parameter `param`. `previous` is the parameter of the
    /// same group given before (the same one twice, or an excluded alternative);
    /// `out_of_order` says a later group was given before this one.
    Param { param: usize, previous: Option<usize>, out_of_order: bool },
    /// A named argument the routine has no parameter of that name for.
    UnknownName,
    /// A positional argument past the last required parameter group.
    TooMany,
    /// A positional argument without a value where alternatives are to be chosen
    /// (only in a program with syntax errors).
    NoValue,
}

/// Binds a call's arguments one at a time, in the order they are written.
pub struct ArgBinder<'r> {
    params: &'r [ParamInfo],
    groups: &'r [(usize, usize)],
    /// The parameter given for each group so far.
    filled: Vec<Option<usize>>,
    /// The group after the furthest one given so far.
    cursor: usize,
}

impl<'r> ArgBinder<'r> {
    /// A binder for `params` grouped as `groups`; `scratch` is reused storage (see
    /// [`ArgBinder::into_scratch`]).
    pub fn new(
        params: &'r [ParamInfo],
        groups: &'r [(usize, usize)],
        mut scratch: Vec<Option<usize>>,
    ) -> ArgBinder<'r> {
        scratch.clear();
        scratch.resize(groups.len(), None);
        ArgBinder { params, groups, filled: scratch, cursor: 0 }
    }

    /// Binds the next argument (not a placeholder). `fits(value, param)` says whether
    /// the argument's value has the type of `param`; it is asked only to choose among
    /// required alternatives, in parameter order.
    pub fn bind(&mut self, arg: &Arg, fits: impl FnMut(ExprId, &ParamInfo) -> bool) -> Binding {
        let param = match arg.name {
            Some(name) => match self.params.iter().position(|p| p.name == name.sym) {
                Some(param) => param,
                None => return Binding::UnknownName,
            },
            None => match self.positional(arg, fits) {
                Ok(param) => param,
                Err(binding) => return binding,
            },
        };
        let group = self.groups.iter().position(|&(start, end)| (start..end).contains(&param)).unwrap_or(0);
        let previous = self.filled[group];
        let out_of_order = group < self.cursor;
        self.filled[group] = Some(param);
        self.cursor = self.cursor.max(group + 1);
        Binding::Param { param, previous, out_of_order }
    }

    /// The required parameter groups no argument was given for, as `(start, end)`
    /// ranges of parameters.
    pub fn missing(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.groups
            .iter()
            .zip(&self.filled)
            .filter(|&(&(start, _), filled)| filled.is_none() && !self.params[start].optional)
            .map(|(&group, _)| group)
    }

    /// Gives back the storage the binder used, for the next call.
    pub fn into_scratch(self) -> Vec<Option<usize>> {
        self.filled
    }

    /// The parameter a positional argument stands for: the first required group not
    /// given past the cursor, else an earlier gap (the arguments are then out of order).
    fn positional(&self, arg: &Arg, mut fits: impl FnMut(ExprId, &ParamInfo) -> bool) -> Result<usize, Binding> {
        let unfilled_required = |g: &usize| self.filled[*g].is_none() && !self.params[self.groups[*g].0].optional;
        let n_groups = self.groups.len();
        let group =
            (self.cursor..n_groups).find(unfilled_required).or_else(|| (0..self.cursor).find(unfilled_required));
        let Some(group) = group else { return Err(Binding::TooMany) };
        let (start, end) = self.groups[group];
        if end - start == 1 {
            return Ok(start);
        }
        // Required alternatives (built-ins only): the one whose type fits, else the first.
        let value = arg.value.ok_or(Binding::NoValue)?;
        Ok((start..end).find(|&p| fits(value, &self.params[p])).unwrap_or(start))
    }
}

/// Whether an argument of type `ty` with `rank` dimensions fits parameter `param`
/// among alternatives: the same type (aliases followed) and the same rank.
pub fn fits(types: &Types, param: &ParamInfo, ty: TypeId, rank: u8) -> bool {
    types.same(param.ty, ty) && param.rank == rank
}

/// The argument each parameter of `routine` gets, in parameter order (placeholders
/// and arguments that fit nowhere are left out; the last one given for a parameter wins).
pub fn bind_args<'a>(
    routine: &RoutineInfo,
    args: &'a [Arg],
    mut fits: impl FnMut(ExprId, &ParamInfo) -> bool,
) -> Vec<Option<&'a Arg>> {
    let mut bound: Vec<Option<&Arg>> = vec![None; routine.params.len()];
    let mut binder = ArgBinder::new(&routine.params, &routine.groups, Vec::new());
    for arg in args.iter().filter(|arg| arg.kind != ArgKind::Placeholder) {
        if let Binding::Param { param, .. } = binder.bind(arg, &mut fits) {
            bound[param] = Some(arg);
        }
    }
    bound
}
