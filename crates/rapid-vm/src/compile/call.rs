//! Calls: the callee and the parameter each argument goes to as the checker resolved
//! them (`rapid_sema::ItemFacts`), then arguments passed as values (IN), places (VAR,
//! INOUT, PERS), absent, switches, or conditionally forwarded optional parameters.

use rapid_sema::symbols::{ParamInfo, RoutineInfo};
use rapid_syntax::ast::{Arena, Arg, ArgKind, ArgList, ExprKind, ParamMode};
use rapid_syntax::Span;

use super::expr::expected_dims;
use super::{CompileError, LocalKind, Resolved, RoutineCompiler};

/// Where a call is written, which is how the checker's facts name it.
#[derive(Debug, Clone, Copy)]
pub(crate) enum CallOf {
    /// A function call, the expression `id`.
    Expr(rapid_syntax::ast::ExprId),
    /// A procedure call statement whose routine name starts at this byte.
    Stmt(u32),
}
use crate::builtins::{self, Compiled};
use crate::ir::{ArgOrigin, ArgSpec, CallSite, Callee, Instr, LateArg, LateArgKind};

/// The built-ins the compiler turns into instructions of its own (registered here,
/// beside the code that compiles them; Break and ArgName, which also run as
/// functions, are registered with their families).
pub(crate) static FAMILY: builtins::Family = builtins::Family {
    file: file!(),
    builtins: &[
        builtins::compiled("Present", Compiled::Present),
        builtins::compiled("CallByVar", Compiled::CallByVar),
        builtins::compiled("Type", Compiled::Type),
        // Its compiled loop calls `run` only for the \Visualize box.
        builtins::native("WaitUntil", builtins::io_visualize::wait_until_box).compiled_as(Compiled::WaitUntil),
        builtins::compiled("Continue", Compiled::Continue),
    ],
};

impl RoutineCompiler<'_> {
    /// A call of `name` with `args`, written as `of` says: a function call in an
    /// expression pushes its result.
    pub(crate) fn call(&mut self, arena: &Arena, args: ArgList, span: Span, of: CallOf) -> Result<(), CompileError> {
        let in_expr = matches!(of, CallOf::Expr(_));
        let Some(Resolved::Routine(idx)) = self.callee(of) else {
            if in_expr {
                // A function defined nowhere raises ERR_REFUNKFUN when the call is
                // executed (its arguments are not evaluated).
                let name_text = span.text(self.text).split('(').next().unwrap_or("").trim();
                let name_idx = self.st.code.constant(crate::value::Value::Str(name_text.into()));
                self.st.code.emit(Instr::UnknownFunc(name_idx));
                return Ok(());
            }
            // Calls to undefined procedures raise ERR_REFUNKPRC when executed.
            let site = CallSite { callee: Callee::Late, args: Vec::new(), n_pushed: 0, late_args: Vec::new() };
            let name_text = span.text(self.text).split(|c: char| c == '(' || c.is_whitespace()).next().unwrap_or("");
            let name_idx = self.st.code.constant(crate::value::Value::Str(name_text.into()));
            self.st.code.emit(Instr::Const(name_idx));
            let late = self.late_site(arena, args, site)?;
            self.st.code.emit(Instr::LateCall(late));
            return Ok(());
        };
        let info = self.prog.routines[idx as usize].clone();
        let callee = match info.chapter {
            None => Callee::Routine(idx),
            Some(chapter) => {
                let Some(id) = self.builtins.lookup(&info.display) else {
                    return Err(match builtins::option_refusal(&info.display, chapter) {
                        Some(message) => self.error(span, message),
                        None => self.unsupported(span, &format!("the built-in `{}`", info.display)),
                    });
                };
                match self.builtins.get(id).compiled {
                    Some(Compiled::Present) => return self.present(arena, args, span),
                    Some(Compiled::CallByVar) => return self.call_by_var(arena, args),
                    Some(Compiled::Break) if !self.st.loops.is_empty() => {
                        // RW 6.15 (manual §1.5): Break ends the innermost enclosing loop.
                        // Outside a loop it keeps its older meaning, a debugging stop.
                        let jump = self.st.code.emit(Instr::Jump(0));
                        if let Some(jumps) = self.st.loops.last_mut() {
                            jumps.breaks.push(jump);
                        }
                        return Ok(());
                    }
                    Some(Compiled::Continue) => {
                        // Manual §1.5: skip the rest of the loop, start its next iteration.
                        let Some(jumps) = self.st.loops.last_mut() else {
                            return Err(self.error(span, "Continue is only allowed inside a FOR or WHILE loop"));
                        };
                        let jump = self.st.code.emit(Instr::Jump(0));
                        jumps.continues.push(jump);
                        return Ok(());
                    }
                    Some(Compiled::Type) => return self.type_name(arena, args, span),
                    Some(Compiled::WaitUntil) => return self.wait_until(arena, &info, args, span),
                    Some(Compiled::ArgName) => return self.arg_name(arena, &info, id, args, span),
                    Some(Compiled::Break) | None => Callee::Builtin(id),
                }
            }
        };
        let bound = self.bound_args(arena, &info, args, span)?;
        let mut specs = Vec::with_capacity(info.params.len());
        let mut n_pushed = 0u16;
        let takes_signals = info.flags.takes_signals;
        for (param, arg) in info.params.iter().zip(&bound) {
            let spec = match arg {
                None => ArgSpec::Absent,
                Some(arg) => self.arg(arena, param, arg, takes_signals)?,
            };
            if matches!(spec, ArgSpec::Value | ArgSpec::Place) {
                n_pushed += 1;
            }
            specs.push(spec);
        }
        // ArgName in the callee looks through its parameters to these arguments.
        // Built-ins that identify data by its name (a syncident, a taskid) read it there too.
        let names_data = info.flags.names_data;
        let origins = match callee {
            Callee::Routine(_) => Some(self.origins(arena, &bound, &specs)),
            Callee::Builtin(_) if names_data => Some(self.origins(arena, &bound, &specs)),
            _ => None,
        };
        let site = self.site_with(CallSite { callee, args: specs, n_pushed, late_args: Vec::new() }, origins);
        self.st.code.emit(Instr::Call(site));
        Ok(())
    }

    /// What the routine name of a call denotes: what the checker found.
    pub(crate) fn callee(&self, of: CallOf) -> Option<Resolved> {
        let found = self.facts.and_then(|facts| match of {
            CallOf::Expr(id) => facts.name(id),
            CallOf::Stmt(name_start) => facts.procedure(name_start),
        });
        found.and_then(|denotes| self.denoted(denotes))
    }

    /// The argument each parameter of `info` gets from `args`, as the checker bound
    /// them (`rapid_sema::bind`).
    fn bound_args<'a>(
        &self,
        arena: &'a Arena,
        info: &RoutineInfo,
        args: ArgList,
        span: Span,
    ) -> Result<Vec<Option<&'a Arg>>, CompileError> {
        let Some(bound) = self.facts.and_then(|facts| facts.bound(args, info.params.len())) else {
            // The checker bound every argument of a call it checked without error.
            return Err(
                self.error(span, format!("the arguments of `{}` were not matched by the checker", info.display))
            );
        };
        Ok(bound.into_iter().map(|arg| arg.and_then(|idx| arena.args.get(idx as usize))).collect())
    }

    /// A call of WaitRob (no arguments): the program waits for the robot to stand still.
    fn wait_for_robot(&mut self, span: Span) -> Result<(), CompileError> {
        let Some(id) = self.builtins.lookup("WaitRob") else { return Err(self.unsupported(span, "WaitUntil \\InPos")) };
        let wait_rob =
            self.prog.routines.iter().find(|r| r.chapter.is_some() && r.display.eq_ignore_ascii_case("WaitRob"));
        // WaitRob [\InPos] | [\ZeroSpeed]: its switches, not passed.
        let n_params = wait_rob.map_or(2, |info| info.params.len());
        let args = vec![ArgSpec::Absent; n_params];
        let site = self.site(CallSite { callee: Callee::Builtin(id), args, n_pushed: 0, late_args: Vec::new() });
        self.st.code.emit(Instr::Call(site));
        Ok(())
    }

    /// `ArgName(Parameter [\ErrorNumber])`: the Parameter argument is never evaluated
    /// (an absent optional parameter or a switch must give ERR_ARGNAME, not
    /// ERR_NOTPRES); the call site records which data object it names instead.
    fn arg_name(
        &mut self,
        arena: &Arena,
        info: &RoutineInfo,
        id: builtins::BuiltinId,
        args: ArgList,
        span: Span,
    ) -> Result<(), CompileError> {
        let bound = self.bound_args(arena, info, args, span)?;
        let mut specs = Vec::with_capacity(info.params.len());
        let mut n_pushed = 0u16;
        for (idx, (param, arg)) in info.params.iter().zip(&bound).enumerate() {
            let spec = match arg {
                Some(_) if idx == 0 => ArgSpec::Absent,
                Some(arg) => self.arg(arena, param, arg, false)?,
                None => ArgSpec::Absent,
            };
            if matches!(spec, ArgSpec::Value | ArgSpec::Place) {
                n_pushed += 1;
            }
            specs.push(spec);
        }
        let origin = match bound.first().copied().flatten().and_then(|arg| arg.value) {
            Some(value) => self.data_origin(arena, value),
            None => ArgOrigin::None,
        };
        let site = CallSite { callee: Callee::Builtin(id), args: specs, n_pushed, late_args: Vec::new() };
        let site = self.site_with(site, Some(Box::new([origin])));
        self.st.code.emit(Instr::Call(site));
        Ok(())
    }

    /// Where each bound argument came from, in parameter order.
    fn origins(&self, arena: &Arena, bound: &[Option<&Arg>], specs: &[ArgSpec]) -> Box<[ArgOrigin]> {
        bound
            .iter()
            .zip(specs)
            .map(|(arg, spec)| match (spec, arg.and_then(|a| a.value)) {
                (ArgSpec::Conditional { slot, .. }, _) => ArgOrigin::Param(*slot),
                (ArgSpec::Value | ArgSpec::Place, Some(value)) => self.data_origin(arena, value),
                _ => ArgOrigin::None,
            })
            .collect()
    }

    /// The data object an argument names: the whole object for an element or a
    /// component, a parameter of this routine, or nothing for any other expression.
    // uncertain: a parenthesised name `(x)` is taken as an expression (no data object).
    // uncertain: routine data and loop variables are named as written at the argument;
    // module data by its declaration.
    fn data_origin(&self, arena: &Arena, value: rapid_syntax::ast::ExprId) -> ArgOrigin {
        let mut id = value;
        loop {
            match arena.expr(id).kind {
                ExprKind::Index { base, .. } | ExprKind::Field { base, .. } => id = base,
                ExprKind::Name(_) => break,
                _ => return ArgOrigin::None,
            }
        }
        match self.name(id) {
            Some(Resolved::Global(idx)) => match self.prog.data(idx) {
                Some(data) => ArgOrigin::Data(data.display.as_str().into()),
                None => ArgOrigin::None,
            },
            Some(Resolved::Local(local)) => match local.kind {
                LocalKind::Param { .. } => ArgOrigin::Param(local.slot),
                LocalKind::Data | LocalKind::LoopVar => ArgOrigin::Data(arena.expr(id).span.text(self.text).into()),
                LocalKind::Temp => ArgOrigin::None,
            },
            _ => ArgOrigin::None,
        }
    }

    fn site(&mut self, site: CallSite) -> u32 {
        self.site_with(site, None)
    }

    /// The index of call site `site` whose arguments come from `origins` (recorded
    /// for ArgName): the one made before for an identical call, else a new one.
    /// Sharing is safe because a site is read only, never written, when it runs.
    fn site_with(&mut self, site: CallSite, origins: Option<Box<[ArgOrigin]>>) -> u32 {
        let key = (site, origins);
        if let Some(&idx) = self.st.sites_seen.get(&key) {
            return idx;
        }
        let idx = self.st.code.sites.len() as u32;
        self.st.code.sites.push(key.0.clone());
        // New sites have rising indices: `arg_origins` stays sorted by site.
        if let Some(origins) = &key.1 {
            self.st.code.arg_origins.push((idx, origins.clone()));
        }
        self.st.sites_seen.insert(key, idx);
        idx
    }

    fn arg(
        &mut self,
        arena: &Arena,
        param: &ParamInfo,
        arg: &Arg,
        takes_signals: bool,
    ) -> Result<ArgSpec, CompileError> {
        let by_ref = param.mode != ParamMode::In;
        match arg.kind {
            ArgKind::Optional if arg.value.is_none() => return Ok(ArgSpec::Switch),
            ArgKind::Conditional => {
                let Some(value) = arg.value else { return Ok(ArgSpec::Absent) };
                let ExprKind::Name(_) = arena.expr(value).kind else {
                    return Err(self.unsupported(arg.span, "a conditional argument that is not a parameter name"));
                };
                return match self.name(value) {
                    Some(Resolved::Local(local)) if matches!(local.kind, LocalKind::Param { optional: true, .. }) => {
                        Ok(ArgSpec::Conditional { slot: local.slot, by_ref })
                    }
                    _ => Err(self.error(arg.span, "a conditional argument must name an optional parameter")),
                };
            }
            _ => {}
        }
        let Some(value) = arg.value else { return Ok(ArgSpec::Absent) };
        if by_ref {
            self.place(arena, value)?;
            return Ok(ArgSpec::Place);
        }
        let expect =
            if param.ty == rapid_sema::types::ANY { None } else { Some((param.ty, expected_dims(param.rank, [0; 3]))) };
        // A signal parameter (or AliasIO's and ValidIO's `anytype`) takes the signal
        // itself, not its value.
        let signal_param = self.prog.types.class(param.ty) == rapid_sema::types::ValueClass::SemiValue;
        self.st.signal_as_data = signal_param || (param.ty == rapid_sema::types::ANY && takes_signals);
        self.expr(arena, value, expect)?;
        self.st.signal_as_data = false;
        Ok(ArgSpec::Value)
    }

    /// `Type(Data [\BaseName])`: the name of the data's declared type — an alias's own
    /// name, or with `\BaseName` the type it stands for. Known when compiling, so the
    /// call becomes a constant.
    // uncertain: the manual does not say whether the indices of an element argument
    // are evaluated; the name does not depend on them, so they are not.
    fn type_name(&mut self, arena: &Arena, args: ArgList, span: Span) -> Result<(), CompileError> {
        let args = arena.args(args);
        let mut base_name = false;
        let mut data = None;
        for arg in args {
            match (arg.kind, arg.value) {
                (ArgKind::Optional, None) => base_name = true,
                (ArgKind::Conditional, _) => {
                    return Err(self.unsupported(arg.span, "Type with a conditional \\BaseName argument"))
                }
                (_, Some(value)) => data = Some(value),
                _ => {}
            }
        }
        let Some((ty, _)) = data.and_then(|value| self.static_type(arena, value)) else {
            return Err(self.error(span, "Type needs a data object as its argument"));
        };
        let types = &self.prog.types;
        let ty = if base_name { types.canonical(ty) } else { ty };
        let name = types.name(ty).to_string();
        let idx = self.st.code.constant(crate::value::Value::Str(name.as_str().into()));
        self.st.code.emit(Instr::Const(idx));
        Ok(())
    }

    /// `Present(p)`: whether optional parameter `p` was passed.
    fn present(&mut self, arena: &Arena, args: ArgList, span: Span) -> Result<(), CompileError> {
        let value = arena.args(args).first().and_then(|a| a.value);
        let name = value.and_then(|v| match arena.expr(v).kind {
            ExprKind::Name(sym) => Some((v, sym)),
            _ => None,
        });
        match name.and_then(|(v, _)| self.name(v)) {
            Some(Resolved::Local(local)) => {
                self.st.code.emit(Instr::Present(local.slot));
                Ok(())
            }
            _ => Err(self.error(span, "Present needs an optional parameter of this routine")),
        }
    }

    /// `WaitUntil [\InPos] Cond [\MaxTime] [\TimeFlag] [\PollRate] [\Visualize] …`: the
    /// condition is evaluated again every poll (0.1 s of controller time by default);
    /// past \MaxTime ERR_WAIT_MAXTIME, or with \TimeFlag the flag is set TRUE and
    /// execution goes on. `\Visualize` shows a message box while it waits
    /// (`builtins/io_visualize.rs`).
    fn wait_until(&mut self, arena: &Arena, info: &RoutineInfo, args: ArgList, span: Span) -> Result<(), CompileError> {
        let bound = self.bound_args(arena, info, args, span)?;
        let arg_of = |name: &str| {
            info.params
                .iter()
                .position(|p| p.display.eq_ignore_ascii_case(name))
                .and_then(|i| bound[i])
                .and_then(|a| a.value)
        };
        let Some(cond) = arg_of("Cond") else { return Err(self.error(span, "WaitUntil needs a condition")) };
        let visualize = info
            .params
            .iter()
            .position(|p| p.display.eq_ignore_ascii_case("Visualize"))
            .is_some_and(|i| bound[i].is_some());
        let (max_time, time_flag, poll_rate) = (arg_of("MaxTime"), arg_of("TimeFlag"), arg_of("PollRate"));
        let in_pos = info.params.iter().position(|p| p.display.eq_ignore_ascii_case("InPos")).and_then(|i| bound[i]);
        if in_pos.is_some() {
            // `\InPos`: the robot first stands at the end of its last move (§2.3), as
            // WaitRob makes the program wait; MaxTime counts from then.
            self.wait_for_robot(span)?;
        }
        let num = self.prog.core.num;
        let dnum = self.prog.core.dnum;
        let start = self.new_local(dnum, [0; 3], 0, LocalKind::Temp);
        self.st.code.emit(Instr::PushTime);
        self.st.code.emit(Instr::StoreLocal(start.slot));
        let top = self.st.code.here();
        self.expr(arena, cond, None)?;
        let to_wait = self.st.code.emit(Instr::JumpIfFalse(0));
        if let Some(flag) = time_flag {
            self.place(arena, flag)?;
            let idx = self.st.code.constant(crate::value::Value::Bool(false));
            self.st.code.emit(Instr::Const(idx));
            self.st.code.emit(Instr::StorePlace);
        }
        let to_done = self.st.code.emit(Instr::Jump(0));
        let here = self.st.code.here();
        self.st.code.patch(to_wait, here);
        if visualize {
            // Each poll that waits: the box opens at the first, closes after \VisualizeTime.
            self.visualize_call(arena, info, &bound, false)?;
        }
        if let Some(max_time) = max_time {
            // elapsed >= MaxTime ?
            self.st.code.emit(Instr::PushTime);
            self.st.code.emit(Instr::LoadLocal(start.slot));
            self.st.code.emit(Instr::Binary(rapid_syntax::ast::BinaryOp::Sub));
            self.expr(arena, max_time, Some((num, [0; 3])))?;
            self.st.code.emit(Instr::Binary(rapid_syntax::ast::BinaryOp::Lt));
            let still_time = self.st.code.emit(Instr::JumpIfFalse(0));
            let to_poll = self.st.code.emit(Instr::Jump(0));
            let timeout = self.st.code.here();
            self.st.code.patch(still_time, timeout);
            match time_flag {
                Some(flag) => {
                    self.place(arena, flag)?;
                    let idx = self.st.code.constant(crate::value::Value::Bool(true));
                    self.st.code.emit(Instr::Const(idx));
                    self.st.code.emit(Instr::StorePlace);
                    let jump = self.st.code.emit(Instr::Jump(0));
                    self.st.exits.push(jump);
                }
                None => {
                    if visualize {
                        self.visualize_call(arena, info, &bound, true)?;
                    }
                    self.st.code.emit(Instr::RaiseWaitTimeout);
                }
            }
            let poll = self.st.code.here();
            self.st.code.patch(to_poll, poll);
        }
        match poll_rate {
            Some(rate) => self.expr(arena, rate, Some((num, [0; 3])))?,
            None => {
                let idx = self.st.code.constant(crate::value::Value::Num(0.1));
                self.st.code.emit(Instr::Const(idx));
            }
        }
        self.st.code.emit(Instr::WaitPop);
        self.st.code.emit(Instr::Jump(top));
        let done = self.st.code.here();
        if visualize {
            // The box closes as the wait ends (no box was shown if it never waited).
            self.visualize_call(arena, info, &bound, true)?;
        }
        self.st.code.patch(to_done, done);
        for jump in std::mem::take(&mut self.st.exits) {
            self.st.code.patch(jump, done);
        }
        Ok(())
    }

    /// A call of WaitUntil's own `run` for its `\Visualize` box: `Cond` is `done` (the
    /// wait ends), the box's arguments are passed as written, the others left out.
    fn visualize_call(
        &mut self,
        arena: &Arena,
        info: &RoutineInfo,
        bound: &[Option<&Arg>],
        done: bool,
    ) -> Result<(), CompileError> {
        let Some(id) = self.builtins.lookup("WaitUntil") else { return Ok(()) };
        const BOX: [&str; 9] =
            ["Visualize", "Header", "Message", "MsgArray", "Wrap", "Icon", "Image", "VisualizeTime", "UIActiveSignal"];
        let mut specs = Vec::with_capacity(info.params.len());
        let mut n_pushed = 0u16;
        for (param, arg) in info.params.iter().zip(bound) {
            let spec = if param.display.eq_ignore_ascii_case("Cond") {
                let idx = self.st.code.constant(crate::value::Value::Bool(done));
                self.st.code.emit(Instr::Const(idx));
                ArgSpec::Value
            } else {
                match arg {
                    Some(arg) if BOX.iter().any(|n| param.display.eq_ignore_ascii_case(n)) => {
                        self.arg(arena, param, arg, info.flags.takes_signals)?
                    }
                    _ => ArgSpec::Absent,
                }
            };
            if matches!(spec, ArgSpec::Value | ArgSpec::Place) {
                n_pushed += 1;
            }
            specs.push(spec);
        }
        let site = self.site(CallSite { callee: Callee::Builtin(id), args: specs, n_pushed, late_args: Vec::new() });
        self.st.code.emit(Instr::Call(site));
        Ok(())
    }

    /// `CallByVar Name, Number`: a late-bound call of the procedure `Name` + `Number`.
    fn call_by_var(&mut self, arena: &Arena, args: ArgList) -> Result<(), CompileError> {
        for arg in arena.args(args) {
            if let Some(value) = arg.value {
                self.expr(arena, value, None)?;
            }
        }
        self.st.code.emit(Instr::NameWithNumber);
        let site = self.site(CallSite { callee: Callee::Late, args: Vec::new(), n_pushed: 0, late_args: Vec::new() });
        self.st.code.emit(Instr::LateCall(site));
        Ok(())
    }

    /// A late-bound call: the callee's name is on the stack. Arguments are kept as
    /// written (position, name, `\`, switch, conditional) and matched to the
    /// callee's parameters when the call runs, since only then is the callee known.
    pub(crate) fn late_site(&mut self, arena: &Arena, args: ArgList, mut site: CallSite) -> Result<u32, CompileError> {
        let mut origins = Vec::new();
        let mut positional = true;
        for arg in arena.args(args) {
            let name = arg.name.map(|n| n.span.text(self.text).to_ascii_lowercase().into_boxed_str());
            let optional = arg.kind != ArgKind::Required;
            positional &= !optional && name.is_none();
            let (kind, by_ref) = match (arg.kind, arg.value) {
                (ArgKind::Placeholder, _) => {
                    return Err(self.unsupported(arg.span, "a placeholder argument in a late-bound call"))
                }
                (ArgKind::Conditional, Some(value)) => {
                    (LateArgKind::Conditional(self.conditional_slot(arena, value)?), false)
                }
                (ArgKind::Optional, None) => (LateArgKind::Switch, false),
                (_, Some(value)) => {
                    let by_ref = self.late_value(arena, value)?;
                    origins.push(self.data_origin(arena, value));
                    site.n_pushed += 1;
                    (LateArgKind::Pushed, by_ref)
                }
                (_, None) => return Err(self.error(arg.span, "an argument without a value")),
            };
            site.late_args.push(LateArg { by_ref, name, optional, kind });
        }
        // ArgName follows arguments by parameter position: known here only when every
        // argument is positional (otherwise the callee decides where each one goes).
        let origins = positional.then(|| origins.into_boxed_slice());
        Ok(self.site_with(site, origins))
    }

    /// Pushes a late-bound call's argument: a place when it is data (the callee may
    /// want a reference), else its value. Answers whether it pushed a place.
    fn late_value(&mut self, arena: &Arena, value: rapid_syntax::ast::ExprId) -> Result<bool, CompileError> {
        let is_data = self.static_type(arena, value).is_some()
            && matches!(arena.expr(value).kind, ExprKind::Name(_) | ExprKind::Index { .. } | ExprKind::Field { .. });
        if is_data {
            self.place(arena, value)?;
        } else {
            self.expr(arena, value, None)?;
        }
        Ok(is_data)
    }

    /// The local slot of the optional parameter a conditional argument (`\A?p`) forwards.
    fn conditional_slot(&self, arena: &Arena, value: rapid_syntax::ast::ExprId) -> Result<u32, CompileError> {
        let expr = arena.expr(value);
        match expr.kind {
            ExprKind::Name(_) => match self.name(value) {
                Some(Resolved::Local(local)) if matches!(local.kind, LocalKind::Param { optional: true, .. }) => {
                    Ok(local.slot)
                }
                _ => Err(self.error(expr.span, "a conditional argument must name an optional parameter")),
            },
            _ => Err(self.error(expr.span, "a conditional argument must name an optional parameter")),
        }
    }
}
