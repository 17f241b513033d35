//! Routines (§1.1.5): PROC, FUNC and TRAP headers, parameter lists, and bodies with
//! their BACKWARD, ERROR and UNDO handlers.

use super::{ROUTINE_END, STMT_LIST_END};
use crate::ast::{Body, BodyItem, ExprId, Param, ParamMode, Routine, RoutineKind, Section};
use crate::error::SyntaxErrorKind;
use crate::parser::Parser;
use crate::span::Span;
use crate::token::{Placeholder, TokenKind as T, TokenSet};

const PARAM_RECOVERY: TokenSet = TokenSet::new(&[T::Comma, T::RParen, T::Backslash]);

impl Parser<'_, '_, '_> {
    /// `PROC name(params) body ENDPROC`, `FUNC type name(params) ... ENDFUNC` or
    /// `TRAP name ... ENDTRAP`, after any LOCAL.
    pub(crate) fn routine(&mut self, start: u32, local: bool) -> Routine {
        let keyword = self.bump();
        let kind = match keyword.kind {
            T::Func => RoutineKind::Func,
            T::Trap => RoutineKind::Trap,
            _ => RoutineKind::Proc,
        };
        let ret_ty = (kind == RoutineKind::Func).then(|| self.name());
        let name = self.name();
        let params = if kind == RoutineKind::Trap { Vec::new() } else { self.param_list() };

        let module_arena = std::mem::take(&mut self.arena);
        let body_start = self.current().span.start;
        let body = if self.skips_bodies() {
            self.skip_body(ROUTINE_END);
            None
        } else {
            self.routine_body_items()
        };
        let body_span = Span { start: body_start, end: self.current().span.start.max(body_start) };
        self.arena = module_arena;

        let end = match kind {
            RoutineKind::Proc => T::Endproc,
            RoutineKind::Func => T::Endfunc,
            RoutineKind::Trap => T::Endtrap,
        };
        if !self.eat(end) {
            if matches!(self.nth(0), T::Endproc | T::Endfunc | T::Endtrap) {
                self.error_expected(end.describe());
                self.bump();
            } else {
                let kw = keyword.span.text(self.text).to_ascii_uppercase();
                let end_word = end.describe().trim_matches('`');
                let routine_name = name.span.text(self.text).to_owned();
                self.error(
                    SyntaxErrorKind::UnclosedBlock,
                    keyword.span,
                    format!("{kw} {routine_name} has no {end_word}"),
                );
            }
        }
        Routine { local, kind, ret_ty, name, params, body_span, body, span: self.span_from(start) }
    }

    /// `( [param {, param | \param}] )`.
    fn param_list(&mut self) -> Vec<Param> {
        let mut params = Vec::new();
        if !self.expect(T::LParen) {
            return params;
        }
        let mut group: u16 = 0;
        let mut first = true;
        while !self.at(T::RParen) && !self.at_eof() && !self.at_set(STMT_LIST_END) {
            let had_comma = !first && self.eat(T::Comma);
            if self.at(T::Backslash) {
                self.bump();
                group += 1;
                self.param_alternatives(&mut params, group, true);
            } else {
                if !first && !had_comma {
                    self.error_expected("`,` between parameters");
                }
                group += 1;
                self.param_alternatives(&mut params, group, false);
            }
            first = false;
        }
        self.expect(T::RParen);
        params
    }

    /// One parameter, then `| param` alternatives sharing its group.
    fn param_alternatives(&mut self, params: &mut Vec<Param>, group: u16, optional: bool) {
        loop {
            let param = self.param(group, optional);
            params.push(param);
            if !self.eat(T::Pipe) {
                return;
            }
        }
    }

    /// `[VAR|PERS|INOUT] type name [{*,*}]`, or `<PAR>` / `<ALT>`.
    fn param(&mut self, group: u16, optional: bool) -> Param {
        let start = self.current().span.start;
        if self.at(T::Placeholder) {
            let token = self.bump();
            let placeholder = Placeholder::from_text(token.span.text(self.text));
            let name = self.missing_name();
            return Param {
                mode: ParamMode::In,
                ty: name,
                name,
                rank: 0,
                optional,
                group,
                placeholder,
                span: token.span,
            };
        }
        let mode = match self.nth(0) {
            T::Var => ParamMode::Var,
            T::Pers => ParamMode::Pers,
            T::Inout => ParamMode::Inout,
            _ => ParamMode::In,
        };
        if mode != ParamMode::In {
            self.bump();
        }
        let ty = self.name();
        let name = self.name();
        let rank = if self.at(T::LBrace) { self.param_rank() } else { 0 };
        if ty.is_placeholder && name.is_placeholder {
            self.recover_until(PARAM_RECOVERY.union(STMT_LIST_END));
        }
        Param { mode, ty, name, rank, optional, group, placeholder: None, span: self.span_from(start) }
    }

    /// `{*}`, `{*,*}`, `{*,*,*}` or `{<DIM>}`.
    fn param_rank(&mut self) -> u8 {
        let open = self.bump();
        let mut rank = 0u8;
        loop {
            if self.eat(T::Star) || self.eat(T::Placeholder) {
                rank = rank.saturating_add(1);
            } else {
                self.error_expected("`*` in an array parameter");
                break;
            }
            if !self.eat(T::Comma) {
                break;
            }
        }
        self.expect(T::RBrace);
        if rank as usize > super::decl::MAX_DIMS {
            let span = self.span_from(open.span.start);
            self.error(
                SyntaxErrorKind::TooManyDimensions,
                span,
                format!("array parameter has {rank} dimensions; RAPID allows at most 3"),
            );
        }
        rank
    }

    /// Routine data, statements and handlers up to (not including) the END keyword.
    /// Returns the body when bodies are kept.
    pub(crate) fn routine_body_items(&mut self) -> Option<Box<Body>> {
        let mut body = Body::default();
        let mut section = Section::Body;
        let mut seen_statement = false;
        loop {
            let token = self.current();
            match token.kind {
                kind if ROUTINE_END.contains(kind) => break,
                T::Var | T::Pers | T::Const | T::Local | T::Task => {
                    if seen_statement || section != Section::Body {
                        self.error(
                            SyntaxErrorKind::UnexpectedToken,
                            token.span,
                            "data declarations must come before the routine's first instruction".into(),
                        );
                    }
                    let local = self.eat(T::Local).then_some(token.span);
                    let task = (local.is_none() && self.eat(T::Task)).then_some(token.span);
                    if !matches!(self.nth(0), T::Var | T::Pers | T::Const) {
                        self.error_expected("VAR, PERS or CONST");
                        continue;
                    }
                    let decl = self.data_decl(token.span.start, local, task);
                    self.emit_body_item(BodyItem::Decl(decl), &mut body, &mut section);
                }
                T::Backward | T::Error | T::Undo => {
                    let next = self.handler_keyword(section);
                    let keyword = token.span;
                    let error_numbers = if next == Section::Error && self.at(T::LParen) {
                        self.error_number_list()
                    } else {
                        Vec::new()
                    };
                    self.emit_body_item(
                        BodyItem::Section { section: next, keyword, error_numbers },
                        &mut body,
                        &mut section,
                    );
                    section = next;
                }
                _ => {
                    seen_statement = true;
                    let stmt = self.stmt();
                    self.emit_body_item(BodyItem::Stmt(stmt), &mut body, &mut section);
                }
            }
        }
        if self.keeps_bodies() {
            body.arena = std::mem::take(&mut self.arena);
            return Some(Box::new(body));
        }
        None
    }

    /// Consumes a handler keyword, checking the order BACKWARD, ERROR, UNDO.
    fn handler_keyword(&mut self, current: Section) -> Section {
        let token = self.bump();
        let next = match token.kind {
            T::Backward => Section::Backward,
            T::Error => Section::Error,
            _ => Section::Undo,
        };
        let rank = |s: Section| match s {
            Section::Body => 0,
            Section::Backward => 1,
            Section::Error => 2,
            Section::Undo => 3,
        };
        if rank(next) <= rank(current) {
            let word = token.span.text(self.text).to_ascii_uppercase();
            self.error(
                SyntaxErrorKind::UnexpectedToken,
                token.span,
                format!("{word} handler out of place: handlers come once each, in the order BACKWARD, ERROR, UNDO"),
            );
        }
        next
    }

    /// `ERROR (n1, n2, ...)`.
    fn error_number_list(&mut self) -> Vec<ExprId> {
        self.bump();
        let mut numbers = Vec::new();
        loop {
            numbers.push(self.expr());
            if !self.eat(T::Comma) {
                break;
            }
        }
        self.expect(T::RParen);
        numbers
    }
}
