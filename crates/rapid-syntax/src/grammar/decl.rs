//! Type definitions (RECORD, ALIAS; §1.2.1) and data declarations (VAR, PERS, CONST;
//! §1.2.2), plus names.

use crate::ast::{Component, DataDecl, DeclScope, ExprId, Name, Storage, TypeDef, TypeDefKind};
use crate::error::SyntaxErrorKind;
use crate::parser::Parser;
use crate::span::Span;
use crate::token::{Placeholder, TokenKind as T, TokenSet};

/// Arrays have at most three dimensions (§1.2.2).
pub(crate) const MAX_DIMS: usize = rapid_limits::ARRAY_DIMENSIONS;

/// Tokens that may follow a name, so a reserved word there was meant as a name.
const AFTER_NAME: TokenSet =
    TokenSet::new(&[T::Semi, T::Assign, T::LBrace, T::LParen, T::Comma, T::RParen, T::Colon, T::Pipe, T::Backslash]);

impl Parser<'_, '_, '_> {
    /// An identifier (or `<ID>`). A reserved word followed by what a name would be
    /// followed by is taken as a misused name, reported, and consumed.
    pub(crate) fn name(&mut self) -> Name {
        let token = self.current();
        match token.kind {
            T::Ident => {
                self.bump();
                self.name_from(token)
            }
            T::Placeholder if token.span.text(self.text) == "<ID>" => {
                self.bump();
                self.name_from(token)
            }
            kind if kind.is_keyword() && !super::ROUTINE_END.contains(kind) && AFTER_NAME.contains(self.nth(1)) => {
                self.bump();
                let word = token.span.text(self.text).to_ascii_uppercase();
                self.error(
                    SyntaxErrorKind::ReservedWordAsName,
                    token.span,
                    format!("`{word}` is a reserved word and cannot be used as a name"),
                );
                self.name_from(token)
            }
            _ => {
                self.error_expected("a name");
                self.missing_name()
            }
        }
    }

    /// `RECORD name { type comp; } ENDRECORD` or `ALIAS base name;`.
    pub(crate) fn type_def(&mut self, start: u32, local: bool) -> TypeDef {
        let keyword = self.bump();
        let kind = if keyword.kind == T::Alias {
            let base = self.name();
            let name = self.name();
            self.expect_semi();
            TypeDefKind::Alias { base, name }
        } else {
            let name = self.name();
            let components = self.record_components(keyword.span);
            TypeDefKind::Record { name, components }
        };
        TypeDef { local, kind, span: self.span_from(start) }
    }

    fn record_components(&mut self, record_keyword: Span) -> Vec<Component> {
        let mut components = Vec::new();
        loop {
            match self.nth(0) {
                T::Endrecord => {
                    self.bump();
                    return components;
                }
                T::Ident => {
                    let start = self.current().span.start;
                    let ty = self.name();
                    let name = self.name();
                    self.expect(T::Semi);
                    components.push(Component { ty, name, span: self.span_from(start) });
                }
                kind if kind.is_keyword() || kind == T::Eof => {
                    self.error(SyntaxErrorKind::UnclosedBlock, record_keyword, "RECORD has no ENDRECORD".into());
                    return components;
                }
                _ => {
                    self.error_expected("a record component or ENDRECORD");
                    self.bump();
                }
            }
        }
    }

    /// `(VAR | PERS | CONST) type name [{dims}] [:= init];` after any LOCAL/TASK.
    pub(crate) fn data_decl(&mut self, start: u32, local: Option<Span>, task: Option<Span>) -> DataDecl {
        let storage = match self.bump().kind {
            T::Pers => Storage::Pers,
            T::Const => Storage::Const,
            _ => Storage::Var,
        };
        let (scope, scope_span) = match (local, task) {
            (Some(span), _) => (DeclScope::Local, Some(span)),
            (None, Some(span)) => (DeclScope::Task, Some(span)),
            (None, None) => (DeclScope::Global, None),
        };
        if storage == Storage::Const && scope == DeclScope::Task {
            let span = scope_span.unwrap_or_default();
            self.error(SyntaxErrorKind::UnexpectedToken, span, "TASK applies only to PERS and VAR declarations".into());
        }
        let ty = self.name();
        let name = self.name();
        let dims = if self.at(T::LBrace) { self.decl_dims() } else { Vec::new() };
        let init = if self.eat(T::Assign) { Some(self.expr()) } else { None };
        if !self.expect_semi() {
            self.recover_until(TokenSet::new(&[T::Semi]).union(super::STMT_LIST_END).union(super::ITEM_START));
            self.eat(T::Semi);
        }
        DataDecl { scope, scope_span, storage, ty, name, dims, init, span: self.span_from(start) }
    }

    fn decl_dims(&mut self) -> Vec<ExprId> {
        let open = self.bump();
        let mut dims = Vec::new();
        loop {
            if self.at(T::Placeholder) && self.current().span.text(self.text) == "<DIM>" {
                let token = self.bump();
                dims.push(self.arena.alloc(crate::ast::ExprKind::Placeholder(Placeholder::Dim), token.span));
            } else {
                dims.push(self.expr());
            }
            if !self.eat(T::Comma) {
                break;
            }
        }
        self.expect(T::RBrace);
        if dims.len() > MAX_DIMS {
            let span = self.span_from(open.span.start);
            self.error(
                SyntaxErrorKind::TooManyDimensions,
                span,
                format!("array has {} dimensions; RAPID allows at most {MAX_DIMS}", dims.len()),
            );
        }
        dims
    }
}
