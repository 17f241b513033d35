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

#[cfg(test)]
mod tests {
    use std::rc::Rc;

    use rapid_syntax::ast::{Name, ParamMode, RoutineKind};
    use rapid_syntax::{Interner, Span};

    use super::*;
    use crate::symbols::DeclOrigin;
    use crate::types::{ANY, SWITCH};

    /// `PROC p(num A, num V | dnum D, \switch S | num T, \num O)`: groups A, V|D,
    /// S|T, O; the last two optional. Types do not matter here (the callers' `fits`
    /// decides alternatives), so every value parameter has the same one.
    fn routine(interner: &mut Interner) -> RoutineInfo {
        let param = |interner: &mut Interner, name: &str, ty, optional, group| ParamInfo {
            name: interner.intern(name),
            display: name.to_string(),
            ty,
            rank: 0,
            mode: ParamMode::In,
            optional,
            group,
        };
        let params: Rc<[ParamInfo]> = Rc::from(vec![
            param(interner, "A", ANY, false, 0),
            param(interner, "V", ANY, false, 1),
            param(interner, "D", ANY, false, 1),
            param(interner, "S", SWITCH, true, 2),
            param(interner, "T", ANY, true, 2),
            param(interner, "O", ANY, true, 3),
        ]);
        let groups = crate::symbols::group_ranges(&params);
        RoutineInfo {
            display: "p".into(),
            kind: RoutineKind::Proc,
            ret: None,
            params,
            groups,
            chapter: None,
            flags: Default::default(),
            has_placeholders: false,
            origin: DeclOrigin::Routine,
        }
    }

    /// A positional argument with value `n`.
    fn positional(n: u32) -> Arg {
        Arg { kind: ArgKind::Required, name: None, value: Some(ExprId(n)), span: Span::default(), after_comma: true }
    }

    /// `\name:=n`, or the switch `\name` without `n`.
    fn optional(interner: &mut Interner, name: &str, n: Option<u32>) -> Arg {
        let name = Name { sym: interner.intern(name), span: Span::default(), is_placeholder: false };
        Arg {
            kind: ArgKind::Optional,
            name: Some(name),
            value: n.map(ExprId),
            span: Span::default(),
            after_comma: true,
        }
    }

    fn binder(info: &RoutineInfo) -> ArgBinder<'_> {
        ArgBinder::new(&info.params, &info.groups, Vec::new())
    }

    fn param(param: usize, previous: Option<usize>, out_of_order: bool) -> Binding {
        Binding::Param { param, previous, out_of_order }
    }

    #[test]
    fn groups_are_runs_of_alternatives() {
        let info = routine(&mut Interner::default());
        assert_eq!(&info.groups[..], &[(0, 1), (1, 3), (3, 5), (5, 6)]);
    }

    #[test]
    fn positional_arguments_fill_the_required_groups_in_order() {
        let info = routine(&mut Interner::default());
        let mut b = binder(&info);
        assert_eq!(b.bind(&positional(0), |_, _| false), param(0, None, false));
        // No alternative fits: the first of the group.
        assert_eq!(b.bind(&positional(1), |_, _| false), param(1, None, false));
        // Both required groups are given; optional ones take no positional argument.
        assert_eq!(b.bind(&positional(2), |_, _| true), Binding::TooMany);
        assert_eq!(b.missing().count(), 0);
    }

    #[test]
    fn an_alternative_is_chosen_by_what_fits_and_asked_in_order() {
        let info = routine(&mut Interner::default());
        let mut b = binder(&info);
        b.bind(&positional(0), |_, _| unreachable!("a group of one is not chosen from"));
        let mut asked = Vec::new();
        let got = b.bind(&positional(7), |value, p| {
            asked.push((value, p.display.clone()));
            p.display == "D"
        });
        assert_eq!(got, param(2, None, false));
        assert_eq!(asked, vec![(ExprId(7), "V".to_string()), (ExprId(7), "D".to_string())]);
    }

    #[test]
    fn a_named_argument_moves_the_cursor_and_earlier_gaps_are_out_of_order() {
        let mut interner = Interner::default();
        let info = routine(&mut interner);
        let mut b = binder(&info);
        assert_eq!(b.bind(&optional(&mut interner, "O", Some(0)), |_, _| false), param(5, None, false));
        // Past O no required group is free: the first gap, A, then V|D, out of order.
        assert_eq!(b.bind(&positional(1), |_, _| false), param(0, None, true));
        assert_eq!(b.bind(&positional(2), |_, _| false), param(1, None, true));
    }

    #[test]
    fn excluded_alternatives_and_repeats_name_the_one_given_before() {
        let mut interner = Interner::default();
        let info = routine(&mut interner);
        let mut b = binder(&info);
        b.bind(&positional(0), |_, _| false);
        b.bind(&positional(1), |_, _| false);
        assert_eq!(b.bind(&optional(&mut interner, "S", None), |_, _| false), param(3, None, false));
        // The cursor is past S | T now, so the group is also behind it.
        assert_eq!(b.bind(&optional(&mut interner, "T", Some(2)), |_, _| false), param(4, Some(3), true));
        assert_eq!(b.bind(&optional(&mut interner, "T", Some(3)), |_, _| false), param(4, Some(4), true));
    }

    #[test]
    fn unknown_names_missing_groups_and_values_are_told_apart() {
        let mut interner = Interner::default();
        let info = routine(&mut interner);
        let mut b = binder(&info);
        assert_eq!(b.bind(&optional(&mut interner, "X", Some(0)), |_, _| false), Binding::UnknownName);
        b.bind(&positional(1), |_, _| false);
        let no_value = Arg { value: None, ..positional(0) };
        assert_eq!(b.bind(&no_value, |_, _| true), Binding::NoValue);
        // A was given; V | D was not (a value-less argument binds nothing).
        assert_eq!(b.missing().collect::<Vec<_>>(), vec![(1, 3)]);
    }

    #[test]
    fn bind_args_gives_each_parameter_its_last_argument() {
        let mut interner = Interner::default();
        let info = routine(&mut interner);
        let args = [
            positional(0),
            positional(1),
            optional(&mut interner, "T", Some(2)),
            optional(&mut interner, "T", Some(3)),
            Arg { kind: ArgKind::Placeholder, ..positional(9) },
        ];
        let bound = bind_args(&info, &args, |_, p| p.display == "D");
        let values: Vec<Option<ExprId>> = bound.iter().map(|a| a.and_then(|a| a.value)).collect();
        assert_eq!(values, vec![Some(ExprId(0)), None, Some(ExprId(1)), None, Some(ExprId(3)), None]);
    }
}
