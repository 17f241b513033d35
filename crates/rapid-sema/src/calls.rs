//! Routine calls (§1.1.5 "过程调用", §1.3.4): arguments matched to parameters by
//! position and name, optional, switch, mutually exclusive and conditional
//! arguments, and access modes (IN, VAR, INOUT, PERS).

use rapid_syntax::ast::{Arena, Arg, ArgKind, ArgList, ExprId, ExprKind, Name, ParamMode, RoutineKind};
use rapid_syntax::{Span, Symbol};

use crate::bind::{self, ArgBinder, Binding};
use crate::checker::Checker;
use crate::codes::Code;
use crate::expr::{Expect, Ty};
use crate::symbols::{DataKind, Def, ParamInfo, ANY_RANK};
use crate::types;

impl Checker<'_> {
    /// `name(args)` in an expression.
    pub(crate) fn call_expr(&mut self, arena: &Arena, id: ExprId, name: Symbol, args: ArgList, span: Span) -> Ty {
        let name_text = self.text(span).split('(').next().unwrap_or("").trim().to_string();
        let def = self.lookup(name);
        self.note_name(id, def);
        match def {
            Some(Def::Routine(idx)) if self.routine(idx).kind == RoutineKind::Func => {
                self.check_args(idx, arena, args, span);
                self.routine(idx).ret.map_or(Ty::ERROR, Ty::scalar)
            }
            Some(_) => {
                self.diag(Code::NotAFunction, span, format!("`{name_text}` is not a function"));
                self.type_args_leniently(arena, args);
                Ty::ERROR
            }
            None => {
                let note = crate::options::note_for(&name_text);
                // The controller links late: the call raises ERR_REFUNKFUN only when it
                // is executed (a module calling another's function that a cell does not
                // load still runs, as abb_motion_program_exec's documented setup does).
                let message = format!(
                    "no function `{name_text}` is defined in this task; calling it raises ERR_REFUNKFUN at run time{note}"
                );
                self.undefined(Code::UndefinedFunction, span, name, message);
                self.type_args_leniently(arena, args);
                Ty::ERROR
            }
        }
    }

    /// `name args;` as an instruction.
    pub(crate) fn proc_call(&mut self, arena: &Arena, name: Name, args: ArgList, span: Span) {
        if name.is_placeholder {
            return self.type_args_leniently(arena, args);
        }
        let text = self.text(name.span);
        let def = self.lookup(name.sym);
        if self.facts.recording {
            let denotes = self.denotes(def);
            self.facts.set_procedure(name.span.start, denotes);
        }
        match def {
            Some(Def::Routine(idx)) => match self.routine(idx).kind {
                RoutineKind::Proc => self.check_args(idx, arena, args, span),
                RoutineKind::Trap => {
                    self.diag(
                        Code::TrapCalled,
                        name.span,
                        format!("`{text}` is a TRAP routine: traps run on interrupts and cannot be called"),
                    );
                }
                RoutineKind::Func => {
                    self.diag(
                        Code::NotAProcedure,
                        name.span,
                        format!("`{text}` is a function, not a procedure; use its value in an expression"),
                    );
                    self.type_args_leniently(arena, args);
                }
            },
            Some(_) => {
                self.diag(Code::NotAProcedure, name.span, format!("`{text}` is not a procedure"));
                self.type_args_leniently(arena, args);
            }
            None => {
                let message = format!(
                    "no procedure `{text}` is defined in this task; calling it raises ERR_REFUNKPRC at run time{}",
                    crate::options::note_for(text)
                );
                self.undefined(Code::UndefinedProcedure, name.span, name.sym, message);
                self.type_args_leniently(arena, args);
            }
        }
    }

    /// Types argument expressions of a call that cannot be matched, so names inside
    /// them are still resolved.
    pub(crate) fn type_args_leniently(&mut self, arena: &Arena, args: ArgList) {
        for arg in arena.args(args) {
            match (arg.value, arg.kind) {
                (Some(value), ArgKind::Required | ArgKind::Optional) => {
                    self.expr(arena, value, Some(Expect::scalar(types::ANY)));
                }
                // The parameter a conditional argument forwards (a late-bound call's
                // `\opt?opt`), for the compiler; the call is matched when it runs.
                (Some(value), ArgKind::Conditional) if self.facts.recording => {
                    if let ExprKind::Name(sym) = arena.expr(value).kind {
                        let def = self.lookup(sym);
                        self.note_name(value, def);
                    }
                }
                _ => {}
            }
        }
    }

    fn check_args(&mut self, routine: u32, arena: &Arena, args: ArgList, call_span: Span) {
        let info = self.routine(routine);
        // An option routine whose parameter list is not public: only its name is known.
        if info.has_placeholders || info.flags.unchecked_args {
            return self.bind_args_leniently(routine, arena, args);
        }
        let (params, groups, builtin) = (info.params.clone(), info.groups.clone(), info.chapter.is_some());
        let mut binder = ArgBinder::new(&params, &groups, std::mem::take(&mut self.filled_scratch));
        let mut has_placeholder = false;
        for (arg_idx, arg) in (args.start as usize..).zip(arena.args(args)) {
            if arg.kind == ArgKind::Placeholder {
                has_placeholder = true;
                self.facts.set_param(arg_idx, None);
                continue;
            }
            // Required alternatives: the argument is typed once, then matched.
            let mut got = None;
            let binding = binder.bind(arg, |value, param| {
                let got = *got.get_or_insert_with(|| self.expr(arena, value, Some(Expect::scalar(types::ANY))));
                bind::fits(&self.types, param, got.ty, got.rank)
            });
            let bound_to = match binding {
                Binding::Param { param, .. } => Some(param),
                _ => None,
            };
            self.facts.set_param(arg_idx, bound_to);
            let Some(param_idx) = self.report_binding(routine, &params, arg, binding) else {
                if let Some(value) = arg.value.filter(|_| arg.kind != ArgKind::Conditional) {
                    self.expr(arena, value, Some(Expect::scalar(types::ANY)));
                }
                continue;
            };
            self.check_arg_value(arena, &params[param_idx], arg, builtin);
        }
        if !has_placeholder {
            for (start, end) in binder.missing() {
                let names: Vec<&str> = params[start..end].iter().map(|p| p.display.as_str()).collect();
                let message =
                    format!("`{}` needs the argument `{}`", self.routine(routine).display, names.join("` or `"));
                self.diag(Code::MissingArgument, call_span, message);
            }
        }
        self.filled_scratch = binder.into_scratch();
    }

    /// The arguments of a routine whose parameters are not checked (an option routine
    /// whose parameter list is not public): typed as [`Checker::type_args_leniently`]
    /// does, and bound without a report, for the compiler.
    fn bind_args_leniently(&mut self, routine: u32, arena: &Arena, args: ArgList) {
        if !self.facts.recording {
            return self.type_args_leniently(arena, args);
        }
        let info = self.routine(routine);
        let (params, groups) = (info.params.clone(), info.groups.clone());
        let mut binder = ArgBinder::new(&params, &groups, std::mem::take(&mut self.filled_scratch));
        for (arg_idx, arg) in (args.start as usize..).zip(arena.args(args)) {
            let got = match (arg.value, arg.kind) {
                (Some(value), ArgKind::Required | ArgKind::Optional) => {
                    Some(self.expr(arena, value, Some(Expect::scalar(types::ANY))))
                }
                _ => None,
            };
            if arg.kind == ArgKind::Placeholder {
                self.facts.set_param(arg_idx, None);
                continue;
            }
            let binding =
                binder.bind(arg, |_, param| got.is_some_and(|got| bind::fits(&self.types, param, got.ty, got.rank)));
            let bound_to = match binding {
                Binding::Param { param, .. } => Some(param),
                _ => None,
            };
            self.facts.set_param(arg_idx, bound_to);
        }
        self.filled_scratch = binder.into_scratch();
    }

    /// Reports an argument bound to no parameter, or to one it cannot stand for as
    /// written; answers the parameter it stands for.
    fn report_binding(&mut self, routine: u32, params: &[ParamInfo], arg: &Arg, binding: Binding) -> Option<usize> {
        let (param_idx, previous, out_of_order) = match binding {
            Binding::Param { param, previous, out_of_order } => (param, previous, out_of_order),
            Binding::UnknownName => {
                // An option routine whose manual is not public may take optional
                // arguments its declaration does not list: the caller types the value.
                let info = self.routine(routine);
                if info.flags.open_optionals && arg.kind != ArgKind::Required {
                    return None;
                }
                let name = arg.name?;
                let text = self.text(name.span);
                let shown = if arg.kind == ArgKind::Required { text.to_string() } else { format!("\\{text}") };
                let message = format!("`{}` has no parameter `{shown}`", info.display);
                self.diag(Code::UnknownArgument, name.span, message);
                return None;
            }
            Binding::TooMany => {
                let message = format!("too many arguments for `{}`", self.routine(routine).display);
                self.diag(Code::TooManyArguments, arg.span, message);
                return None;
            }
            Binding::NoValue => return None,
        };
        if let Some(name) = arg.name {
            let text = self.text(name.span);
            let optional_syntax = arg.kind != ArgKind::Required;
            if params[param_idx].optional != optional_syntax {
                let routine_name = &self.routine(routine).display;
                let message = if params[param_idx].optional {
                    format!("parameter `{text}` of `{routine_name}` is optional: write it as `\\{text}`")
                } else {
                    format!("parameter `{text}` of `{routine_name}` is required: write it without `\\`")
                };
                self.diag(Code::RequiredAsOptional, name.span, message);
            }
        }
        if let Some(previous) = previous {
            let (a, b) = (&params[param_idx].display, &params[previous].display);
            let message = if previous == param_idx {
                format!("argument `{a}` is given twice")
            } else {
                format!("`{a}` and `{b}` exclude each other; give only one")
            };
            self.diag(Code::DuplicateArgument, arg.span, message);
        } else if out_of_order {
            let (name, routine_name) = (&params[param_idx].display, &self.routine(routine).display);
            let message = format!(
                "argument `{name}` is out of order: arguments must follow the order of `{routine_name}`'s parameters"
            );
            self.diag(Code::ArgumentOrder, arg.span, message);
        }
        Some(param_idx)
    }

    /// Checks one argument's value; `builtin` calls may pass non-value data to IN
    /// parameters (the controller passes them by reference).
    fn check_arg_value(&mut self, arena: &Arena, param: &ParamInfo, arg: &Arg, builtin: bool) {
        let name = &param.display;
        match arg.kind {
            ArgKind::Conditional => return self.check_conditional(arena, param, arg),
            ArgKind::Optional if param.is_switch() => {
                if let Some(value) = arg.value {
                    self.diag(
                        Code::SwitchWithValue,
                        arena.expr(value).span,
                        format!("`\\{name}` is a switch: it takes no value"),
                    );
                }
                return;
            }
            ArgKind::Optional if arg.value.is_none() => {
                self.diag(
                    Code::MissingArgumentValue,
                    arg.span,
                    format!("`\\{name}` is not a switch: give it a value with `\\{name}:=...`"),
                );
                return;
            }
            _ => {}
        }
        let Some(value) = arg.value else { return };
        const UNKNOWN_DIMS: [u32; 3] = [0; 3];
        let rank = if param.rank == ANY_RANK { 0 } else { (param.rank as usize).min(3) };
        let expect = Expect { ty: param.ty, dims: &UNKNOWN_DIMS[..rank] };
        if param.mode != ParamMode::In {
            self.check_reference(arena, value, param, builtin);
        }
        let got = self.expr(arena, value, Some(expect));
        if got.ty == types::ERROR {
            return;
        }
        let span = arena.expr(value).span;
        // `anytype` data parameters take arrays too (WriteAnyBin, ValToStr of a record...).
        let rank_ok = match param.rank {
            ANY_RANK => got.rank > 0,
            0 if param.ty == types::ANY => true,
            rank => got.rank == rank,
        };
        if !rank_ok {
            let (want, found) = (self.describe(param.ty, param.rank), self.describe(got.ty, got.rank));
            self.diag(Code::ArrayArgumentMismatch, span, format!("argument `{name}` must be {want}, found {found}"));
            return;
        }
        if !builtin
            && param.mode == ParamMode::In
            && !self.types.is_lenient(param.ty)
            && self.types.class(got.ty) == crate::types::ValueClass::NonValue
        {
            let found = self.type_name(got.ty);
            self.diag(Code::NonValueUse, span, format!("argument `{name}` is an IN parameter, which needs a value; `{found}` is a non-value type (declare the parameter VAR)"));
            return;
        }
        let fits = if param.mode == ParamMode::In {
            self.types.compatible(param.ty, got.ty)
        } else {
            self.types.same(param.ty, got.ty)
        };
        if !fits {
            let (want, found) = (self.describe(param.ty, param.rank), self.describe(got.ty, got.rank));
            self.diag(Code::TypeMismatch, span, format!("argument `{name}` must be {want}, found {found}"));
        }
    }

    /// VAR, INOUT and PERS parameters need a data object of the right kind (§1.1.5).
    /// An INOUT parameter of a built-in also takes part of a persistent.
    // uncertain: the manual's rule for INOUT is "a variable (entire, element or
    // component) or an entire persistent"; but a RobotWare 6.11 backup (ETH's COMPAS
    // RRC) runs `Incr n_WritePtr{nCh}` on a persistent array's element, so built-ins
    // take one. User routines keep the manual's rule.
    fn check_reference(&mut self, arena: &Arena, value: ExprId, param: &ParamInfo, builtin: bool) {
        let span = arena.expr(value).span;
        let name = &param.display;
        let want = match param.mode {
            ParamMode::Var => "a variable",
            ParamMode::Pers => "an entire persistent",
            _ => "a variable or an entire persistent",
        };
        let Some((data, entire)) = self.reference_root(arena, value) else {
            if !matches!(arena.expr(value).kind, ExprKind::Name(_) | ExprKind::Placeholder(_) | ExprKind::Error) {
                self.diag(
                    Code::ArgumentNotReference,
                    span,
                    format!("argument `{name}` must be {want}, not an expression"),
                );
            }
            return;
        };
        let kind = self.data(data).kind;
        let is_var = matches!(kind, DataKind::Var | DataKind::Param(ParamMode::In | ParamMode::Var | ParamMode::Inout));
        let is_pers = matches!(kind, DataKind::Pers | DataKind::Param(ParamMode::Pers | ParamMode::Inout));
        let ok = match param.mode {
            ParamMode::Var => is_var,
            ParamMode::Pers => is_pers && entire,
            _ => is_var || (is_pers && (entire || builtin)),
        };
        if !ok {
            let what = match kind {
                DataKind::Const => "a constant",
                DataKind::LoopVar => "a FOR loop variable",
                DataKind::ReadOnly => "a read-only system variable",
                DataKind::Pers if !entire => "part of a persistent",
                DataKind::Pers => "a persistent",
                _ => "a variable",
            };
            self.diag(
                Code::ArgumentNotReference,
                span,
                format!("argument `{name}` must be {want}, but this is {what}"),
            );
        }
    }

    /// `\Name ? param` forwards an optional parameter of the calling routine.
    fn check_conditional(&mut self, arena: &Arena, param: &ParamInfo, arg: &Arg) {
        let Some(value) = arg.value else { return };
        let span = arena.expr(value).span;
        let forwarded = match arena.expr(value).kind {
            ExprKind::Name(sym) => {
                let def = self.lookup(sym);
                self.note_name(value, def);
                match def {
                    Some(Def::Data(data)) => Some(data),
                    _ => None,
                }
            }
            _ => self.reference_root(arena, value).map(|(data, _)| data),
        };
        match forwarded {
            Some(data) if self.data(data).optional => {
                let info = self.data(data);
                let (ty, rank) = (info.ty, info.rank);
                let fits = param.is_switch() && ty == types::SWITCH
                    || self.types.compatible(param.ty, ty) && (rank == param.rank || param.rank == ANY_RANK);
                if !fits && !param.is_switch() {
                    let (want, found) = (self.describe(param.ty, param.rank), self.describe(ty, rank));
                    let name = &param.display;
                    self.diag(Code::TypeMismatch, span, format!("argument `{name}` must be {want}, found {found}"));
                }
            }
            Some(_) => {
                let text = self.text(span);
                self.diag(Code::ConditionalFromRequired, span, format!("`{text}` is not an optional parameter of this routine, so it cannot be passed on conditionally with `?`"));
            }
            None => {
                self.expr(arena, value, None);
            }
        }
    }
}
