//! Routine bodies, one item at a time as the parser streams them: routine data,
//! statements (§1.4, §1.5), labels and GOTO, RETURN, handlers (§1.12), UNDO (§1.13)
//! and BACKWARD (§1.21) restrictions.

use rapid_syntax::ast::{
    Arena, BodyItem, DataDecl, ExprId, ExprKind, Name, ParamMode, Routine, RoutineKind, Section, Stmt, StmtKind,
};
use rapid_syntax::{Span, Symbol};
use rustc_hash::FxHashMap;

use crate::checker::Checker;
use crate::codes::Code;
use crate::expr::{Expect, What};
use crate::symbols::{DataInfo, DataKind, DeclOrigin, Def};
use crate::types::{self, ValueClass};

/// What the checker knows about the routine whose body it is reading.
#[derive(Debug)]
pub(crate) struct RoutineCtx {
    kind: RoutineKind,
    ret: Option<types::TypeId>,
    name_span: Span,
    section: Section,
    labels: FxHashMap<Symbol, (Span, Vec<u32>)>,
    gotos: Vec<(Symbol, Span, Vec<u32>)>,
    block_path: Vec<u32>,
    next_block: u32,
    has_return: bool,
    /// FOR and WHILE loops around the statement being checked: Break inside one ends
    /// the loop (RW 6.15, manual §1.5) rather than stopping the program.
    loops: u32,
    /// Length of the data table before this routine's parameters and data.
    pub(crate) data_mark: usize,
    /// Routine data and parameter names with their spans (labels may not reuse them).
    local_names: FxHashMap<Symbol, Span>,
}

impl Checker<'_> {
    /// Starts a routine: parameters become routine data.
    pub(crate) fn begin_routine(&mut self, routine: &Routine) {
        let ret = routine.ret_ty.map(|ty| match self.lookup(ty.sym) {
            Some(Def::Type(ty)) => ty,
            _ => types::ERROR,
        });
        self.ctx = Some(RoutineCtx {
            kind: routine.kind,
            ret,
            name_span: routine.name.span,
            section: Section::Body,
            labels: FxHashMap::default(),
            gotos: Vec::new(),
            block_path: vec![0],
            next_block: 1,
            has_return: false,
            loops: 0,
            data_mark: self.datas.len(),
            local_names: FxHashMap::default(),
        });
        let text = &self.files[self.file].text;
        for param in routine.params.iter().filter(|p| p.placeholder.is_none()) {
            // Parameter types were resolved, and reported, when the routine was declared.
            let info = self.with_diagnostics_muted(|ck| ck.param_info(param, false, text));
            let data = DataInfo {
                display: info.display.clone(),
                ty: info.ty,
                rank: info.rank,
                dims: [0; 3],
                kind: DataKind::Param(info.mode),
                const_value: None,
                optional: info.optional,
                origin: DeclOrigin::Routine,
                system_global: false,
            };
            self.add_routine_data(param.name, data);
        }
    }

    fn add_routine_data(&mut self, name: Name, data: DataInfo) -> u32 {
        self.datas.push(data);
        let idx = self.datas.len() as u32 - 1;
        if name.is_placeholder {
            return idx;
        }
        let Some(ctx) = self.ctx.as_mut() else { return idx };
        if ctx.local_names.insert(name.sym, name.span).is_some() {
            let text = self.text(name.span);
            self.diag(Code::DuplicateDeclaration, name.span, format!("`{text}` is declared twice in this routine"));
        }
        self.scopes.routine.insert(name.sym, idx);
        idx
    }

    /// One streamed body item.
    pub(crate) fn body_item(&mut self, item: &BodyItem, arena: &Arena) {
        self.facts.start(arena.exprs.len(), arena.args.len());
        match item {
            BodyItem::Decl(decl) => self.routine_data(decl, arena),
            BodyItem::Section { section, keyword, error_numbers } => {
                self.enter_section(*section, *keyword, error_numbers, arena)
            }
            BodyItem::Stmt(stmt) => self.stmt(arena, stmt),
            BodyItem::End => {}
        }
    }

    fn routine_data(&mut self, decl: &DataDecl, arena: &Arena) {
        let ty = self.resolve_type_name(decl.ty, false);
        self.facts.set_declared(ty);
        let data = self.data_info(decl, ty, false, true, arena, &self.files[self.file].text);
        let idx = self.add_routine_data(decl.name, data);
        self.check_data_decl(decl, arena, idx, true);
    }

    fn enter_section(&mut self, section: Section, keyword: Span, error_numbers: &[ExprId], arena: &Arena) {
        let Some(ctx) = self.ctx.as_mut() else { return };
        ctx.section = section;
        ctx.block_path = vec![ctx.next_block];
        ctx.next_block += 1;
        let kind = ctx.kind;
        if section == Section::Backward && kind != RoutineKind::Proc {
            self.diag(Code::BackwardOutsideProc, keyword, "only a PROC may have a BACKWARD handler".into());
        }
        for &number in error_numbers {
            self.check_handler_number(arena, number);
        }
    }

    /// An `ERROR (n, ...)` entry: an errnum data object or an integer literal.
    fn check_handler_number(&mut self, arena: &Arena, number: ExprId) {
        let expr = arena.expr(number);
        let ok = match expr.kind {
            ExprKind::Num => {
                rapid_syntax::literal::num_value(self.text(expr.span)).is_some_and(|v| v.fract() == 0.0 && v >= 0.0)
            }
            ExprKind::Name(sym) => match self.lookup(sym) {
                Some(Def::Data(data)) => {
                    self.note_name(number, Some(Def::Data(data)));
                    self.data(data).ty == self.core.errnum && self.data(data).rank == 0
                }
                None => {
                    self.expr(arena, number, None);
                    return;
                }
                _ => false,
            },
            ExprKind::Placeholder(_) | ExprKind::Error => true,
            _ => false,
        };
        if !ok {
            let text = self.text(expr.span);
            self.diag(
                Code::BadHandlerErrorNumber,
                expr.span,
                format!("`{text}` is not an error number: use errnum data such as ERR_DIVZERO"),
            );
        }
    }

    /// Ends a routine: resolves GOTOs, checks for RETURN, drops routine data.
    pub(crate) fn end_routine(&mut self) {
        let Some(ctx) = self.ctx.take() else { return };
        for (label, span, path) in &ctx.gotos {
            let text = self.text(*span);
            match ctx.labels.get(label) {
                None => self.diag(Code::UndefinedLabel, *span, format!("no label `{text}` in this routine")),
                Some((_, label_path)) if !path.starts_with(label_path) => self.diag(
                    Code::GotoIntoBlock,
                    *span,
                    format!(
                        "GOTO `{text}` jumps into an IF, FOR, WHILE or TEST body (or another handler) from outside it"
                    ),
                ),
                Some(_) => {}
            }
        }
        for (label, (span, _)) in &ctx.labels {
            if ctx.local_names.contains_key(label) {
                let text = self.text(*span);
                self.diag(Code::DuplicateLabel, *span, format!("label `{text}` has the name of routine data"));
            }
        }
        if ctx.kind == RoutineKind::Func && !ctx.has_return {
            let text = self.text(ctx.name_span);
            self.diag(
                Code::FuncWithoutReturn,
                ctx.name_span,
                format!("FUNC `{text}` has no RETURN: ending without one raises ERR_FNCNORET"),
            );
        }
        self.datas.truncate(ctx.data_mark);
        self.scopes.routine.clear();
        self.scopes.loop_vars.clear();
        self.declare_virtual_signals();
    }

    fn section(&self) -> Section {
        self.ctx.as_ref().map_or(Section::Body, |c| c.section)
    }

    // ---- statements --------------------------------------------------------------

    fn stmt_list(&mut self, arena: &Arena, stmts: &[Stmt]) {
        if let Some(ctx) = self.ctx.as_mut() {
            ctx.block_path.push(ctx.next_block);
            ctx.next_block += 1;
        }
        for stmt in stmts {
            self.stmt(arena, stmt);
        }
        if let Some(ctx) = self.ctx.as_mut() {
            ctx.block_path.pop();
        }
    }

    pub(crate) fn stmt(&mut self, arena: &Arena, stmt: &Stmt) {
        match &stmt.kind {
            StmtKind::Assign { target, value } => self.assignment(arena, *target, *value),
            StmtKind::Call { name, args } => {
                self.undo_restrictions(*name);
                self.proc_call(arena, *name, *args, stmt.span);
            }
            StmtKind::LateCall { callee, args } => {
                let ty = self.expr(arena, *callee, None);
                if ty.ty != types::ERROR && (ty.rank != 0 || self.types.value_of(ty.ty) != self.core.string) {
                    let span = arena.expr(*callee).span;
                    self.diag(
                        Code::LateBindingNotString,
                        span,
                        "the procedure name between `%` must be a string expression".into(),
                    );
                }
                self.type_args_leniently(arena, *args);
            }
            StmtKind::If { cond, then, elifs, els } => {
                self.condition(arena, *cond);
                self.stmt_list(arena, then);
                for elif in elifs {
                    if let Some(cond) = elif.cond {
                        self.condition(arena, cond);
                    }
                    self.stmt_list(arena, &elif.body);
                }
                if let Some(els) = els {
                    self.stmt_list(arena, els);
                }
            }
            StmtKind::CompactIf { cond, stmt } => {
                self.condition(arena, *cond);
                self.stmt(arena, stmt);
            }
            StmtKind::For { var, from, to, step, body } => self.for_stmt(arena, *var, *from, *to, *step, body),
            StmtKind::While { cond, body } => {
                self.condition(arena, *cond);
                self.loop_body(arena, body);
            }
            StmtKind::Test { subject, cases, default } => self.test_stmt(arena, *subject, cases, default.as_deref()),
            StmtKind::Goto(label) => {
                if let Some(ctx) = self.ctx.as_mut() {
                    ctx.gotos.push((label.sym, label.span, ctx.block_path.clone()));
                }
            }
            StmtKind::Label(label) => self.label(*label),
            StmtKind::Return(value) => self.return_stmt(arena, *value, stmt.span),
            StmtKind::Raise(value) => self.raise_stmt(arena, *value, stmt.span),
            StmtKind::Retry | StmtKind::TryNext => {
                if self.section() != Section::Error {
                    let word = if matches!(stmt.kind, StmtKind::Retry) { "RETRY" } else { "TRYNEXT" };
                    self.diag(
                        Code::RetryOutsideErrorHandler,
                        stmt.span,
                        format!("{word} may be used only in an ERROR handler"),
                    );
                }
            }
            StmtKind::Connect { target, trap } => self.connect(arena, *target, *trap),
            StmtKind::Exit | StmtKind::Placeholder(_) | StmtKind::Error => {}
        }
    }

    fn condition(&mut self, arena: &Arena, cond: ExprId) {
        let ty = self.expr(arena, cond, None);
        if ty.ty != types::ERROR && !self.is_bool(ty) {
            let found = self.describe(ty.ty, ty.rank);
            self.diag(
                Code::ConditionNotBool,
                arena.expr(cond).span,
                format!("a condition must be a `bool`, found {found}"),
            );
        }
    }

    fn assignment(&mut self, arena: &Arena, target: ExprId, value: ExprId) {
        let target_ty = self.expr(arena, target, None);
        let target_span = arena.expr(target).span;
        let mut dims = [0u32; 3];
        if let Some((data, entire)) = self.reference_root(arena, target) {
            let problem = self.assignment_problem(data, target_ty);
            if let Some((code, message)) = problem {
                self.diag(code, target_span, message);
                self.expr(arena, value, Some(Expect::scalar(types::ANY)));
                return;
            }
            if entire {
                dims = self.data(data).dims;
            }
        }
        let rank = target_ty.rank.min(3) as usize;
        let expect = Expect { ty: target_ty.ty, dims: &dims[..rank] };
        self.expect_value(arena, value, expect, What::Text("the assigned value"));
    }

    /// Why data `data` may not be assigned a value of `target_ty` (§1.2.1, §1.2.2).
    fn assignment_problem(&self, data: u32, target_ty: crate::expr::Ty) -> Option<(Code, String)> {
        let info = self.data(data);
        let name = &info.display;
        match info.kind {
            DataKind::Const => Some((Code::ReadOnlyWrite, format!("`{name}` is a constant and cannot be assigned"))),
            DataKind::LoopVar => {
                Some((Code::ReadOnlyWrite, format!("`{name}` is a FOR loop variable: it can only be read")))
            }
            DataKind::ReadOnly => Some((Code::ReadOnlyWrite, format!("`{name}` is a read-only system variable"))),
            // What is assigned decides (§1.2.1): a num component of a record that also
            // holds rawbytes is value data, though the record as a whole is not.
            _ => match self.types.class(target_ty.ty) {
                ValueClass::SemiValue => Some((
                    Code::SemiValueWrite,
                    format!("signal `{name}` cannot be assigned; use Set, Reset, SetDO, SetAO or SetGO"),
                )),
                ValueClass::NonValue => {
                    let ty = self.type_name(target_ty.ty);
                    Some((Code::NonValueUse, format!("`{ty}` is a non-value type: its data cannot be assigned")))
                }
                ValueClass::Value => None,
            },
        }
    }

    fn for_stmt(&mut self, arena: &Arena, var: Name, from: ExprId, to: ExprId, step: Option<ExprId>, body: &[Stmt]) {
        let num = Expect::scalar(self.core.num);
        self.expect_value(arena, from, num, What::Text("the FROM value"));
        self.expect_value(arena, to, num, What::Text("the TO value"));
        if let Some(step) = step {
            self.expect_value(arena, step, num, What::Text("the STEP value"));
        }
        let data = DataInfo {
            display: self.text(var.span).to_string(),
            ty: self.core.num,
            rank: 0,
            dims: [0; 3],
            kind: DataKind::LoopVar,
            const_value: None,
            optional: false,
            origin: DeclOrigin::Routine,
            system_global: false,
        };
        self.datas.push(data);
        let idx = self.datas.len() as u32 - 1;
        self.scopes.loop_vars.push((var.sym, idx));
        self.loop_body(arena, body);
        self.scopes.loop_vars.pop();
    }

    /// The statements of a FOR or WHILE loop.
    fn loop_body(&mut self, arena: &Arena, body: &[Stmt]) {
        if let Some(ctx) = self.ctx.as_mut() {
            ctx.loops += 1;
        }
        self.stmt_list(arena, body);
        if let Some(ctx) = self.ctx.as_mut() {
            ctx.loops -= 1;
        }
    }

    fn test_stmt(
        &mut self,
        arena: &Arena,
        subject: ExprId,
        cases: &[rapid_syntax::ast::Case],
        default: Option<&[Stmt]>,
    ) {
        let ty = self.expr(arena, subject, None);
        let value_ok = ty.ty == types::ERROR || self.types.class(ty.ty) != ValueClass::NonValue;
        if !value_ok {
            let name = self.type_name(ty.ty);
            self.diag(
                Code::NonValueUse,
                arena.expr(subject).span,
                format!("TEST needs a value; `{name}` is a non-value type"),
            );
        }
        for case in cases {
            for &value in &case.values {
                if ty.ty == types::ERROR || !value_ok {
                    self.expr(arena, value, Some(Expect::scalar(types::ANY)));
                } else {
                    let dims = vec![0u32; ty.rank as usize];
                    self.expect_value(arena, value, Expect { ty: ty.ty, dims: &dims }, What::Text("a CASE value"));
                }
            }
            self.stmt_list(arena, &case.body);
        }
        if let Some(default) = default {
            self.stmt_list(arena, default);
        }
    }

    fn label(&mut self, label: Name) {
        let Some(ctx) = self.ctx.as_mut() else { return };
        let path = ctx.block_path.clone();
        if ctx.labels.insert(label.sym, (label.span, path)).is_some() {
            let text = self.text(label.span);
            self.diag(Code::DuplicateLabel, label.span, format!("label `{text}` is defined twice in this routine"));
        }
    }

    fn return_stmt(&mut self, arena: &Arena, value: Option<ExprId>, span: Span) {
        let Some(ctx) = self.ctx.as_mut() else { return };
        ctx.has_return = true;
        let (kind, ret, section) = (ctx.kind, ctx.ret, ctx.section);
        if section == Section::Undo {
            self.diag(
                Code::IgnoredInUndo,
                span,
                "RETURN in an UNDO handler is ignored (with an event-log warning)".into(),
            );
        }
        match (kind, value) {
            (RoutineKind::Func, None) => {
                self.diag(Code::ReturnValueMismatch, span, "a FUNC must RETURN a value".into())
            }
            (RoutineKind::Func, Some(value)) => {
                let want = ret.unwrap_or(types::ERROR);
                self.expect_value(arena, value, Expect::scalar(want), What::Text("the returned value"));
            }
            (_, Some(value)) => {
                let word = if kind == RoutineKind::Proc { "PROC" } else { "TRAP" };
                self.diag(Code::ReturnValueMismatch, arena.expr(value).span, format!("a {word} cannot RETURN a value"));
            }
            (_, None) => {}
        }
    }

    fn raise_stmt(&mut self, arena: &Arena, value: Option<ExprId>, span: Span) {
        let section = self.section();
        if section == Section::Undo {
            self.diag(
                Code::IgnoredInUndo,
                span,
                "RAISE in an UNDO handler is ignored (with an event-log warning)".into(),
            );
        }
        let Some(value) = value else {
            if section != Section::Error {
                self.diag(
                    Code::RaiseWithoutNumber,
                    span,
                    "RAISE without an error number may be used only in an ERROR handler".into(),
                );
            }
            return;
        };
        self.expect_value(arena, value, Expect::scalar(self.core.errnum), What::Text("the error number"));
        if let Some(n) = self.const_num(arena, value) {
            if !(1.0..=90.0).contains(&n) || n.fract() != 0.0 {
                self.diag(
                    Code::RaiseNumberRange,
                    arena.expr(value).span,
                    format!("user error numbers are 1..90; RAISE {n} raises ERR_ILLRAISE at run time"),
                );
            }
        }
    }

    fn connect(&mut self, arena: &Arena, target: ExprId, trap: Name) {
        let target_ty = self.expr(arena, target, None);
        let span = arena.expr(target).span;
        match self.reference_root(arena, target) {
            Some((data, _)) => {
                let info = self.data(data);
                let is_var = matches!(info.kind, DataKind::Var | DataKind::Param(ParamMode::Var | ParamMode::Inout));
                if !is_var || !self.types.same(self.core.intnum, target_ty.ty) || target_ty.rank != 0 {
                    let name = info.display.clone();
                    self.diag(
                        Code::ConnectTargetNotVariable,
                        span,
                        format!("CONNECT needs an `intnum` variable; `{name}` is not one"),
                    );
                }
            }
            None if target_ty.ty != types::ERROR => {
                self.diag(Code::ConnectTargetNotVariable, span, "CONNECT needs an `intnum` variable".into());
            }
            None => {}
        }
        if trap.is_placeholder {
            return;
        }
        let text = self.text(trap.span);
        match self.lookup(trap.sym) {
            Some(Def::Routine(idx)) if self.routine(idx).kind == RoutineKind::Trap => {
                self.facts.set_procedure(trap.span.start, crate::facts::Denotes::Decl(Def::Routine(idx)));
            }
            Some(_) => self.diag(Code::NotATrap, trap.span, format!("`{text}` is not a TRAP routine")),
            None => self.diag(Code::NotATrap, trap.span, format!("no TRAP routine `{text}` is defined in this task")),
        }
    }

    /// Stop and Break are ignored in UNDO; motion instructions are not allowed (§1.13).
    /// Break inside a loop is the loop's end (RW 6.15), not the debugging stop §1.13
    /// means: it is not reported.
    fn undo_restrictions(&mut self, name: Name) {
        if self.section() != Section::Undo {
            return;
        }
        let in_loop = self.ctx.as_ref().is_some_and(|c| c.loops > 0);
        let Some(Def::Routine(idx)) = self.lookup(name.sym) else { return };
        let info = self.routine(idx);
        let Some(chapter) = info.chapter else { return };
        let display = info.display.to_ascii_lowercase();
        let text = self.text(name.span);
        if display == "stop" || (display == "break" && !in_loop) {
            self.diag(
                Code::IgnoredInUndo,
                name.span,
                format!("{text} in an UNDO handler is ignored (with an event-log warning)"),
            );
        } else if chapter == "motion" && is_motion_instruction(&display) {
            self.diag(
                Code::MotionInUndo,
                name.span,
                format!("motion instruction {text} is not allowed in an UNDO handler"),
            );
        }
    }
}

fn is_motion_instruction(lower_name: &str) -> bool {
    lower_name.starts_with("move")
        || lower_name.starts_with("search")
        || matches!(lower_name, "triggl" | "triggc" | "triggj" | "triggabsj")
}
