//! Statements (§1.4, §1.5 and the instruction syntax of the kernel): assignment,
//! procedure calls, late binding, IF, FOR, WHILE, TEST, GOTO and labels, RETURN,
//! RAISE, RETRY, TRYNEXT, EXIT and CONNECT.

use super::{STMT_LIST_END, STMT_START};
use crate::ast::{Case, ElseIf, ExprKind, Placeholder, Stmt, StmtKind};
use crate::error::SyntaxErrorKind;
use crate::parser::{Parser, MAX_STMT_DEPTH};
use crate::span::Span;
use crate::token::{TokenKind as T, TokenSet};

/// Where to resume after a broken statement.
const STMT_RECOVERY: TokenSet = STMT_LIST_END.union(STMT_START).union(TokenSet::new(&[T::Semi]));

impl Parser<'_, '_, '_> {
    /// Statements until a token of `STMT_LIST_END`.
    pub(crate) fn stmt_list(&mut self) -> Vec<Stmt> {
        let mut stmts = Vec::new();
        while !self.at_set(STMT_LIST_END) {
            if matches!(self.nth(0), T::Var | T::Pers | T::Const | T::Local) {
                let span = self.current().span;
                self.error(
                    SyntaxErrorKind::UnexpectedToken,
                    span,
                    "data declarations may stand only at the start of a routine".into(),
                );
                let _ = self.data_decl(span.start, None, None);
                continue;
            }
            stmts.push(self.stmt());
        }
        stmts
    }

    /// One statement. Always consumes at least one token unless at a list end.
    pub(crate) fn stmt(&mut self) -> Stmt {
        let start = self.current().span.start;
        if self.stmt_depth >= MAX_STMT_DEPTH && matches!(self.nth(0), T::If | T::For | T::While | T::Test) {
            self.error_too_deep("statements", MAX_STMT_DEPTH);
            self.skip_nested();
            return Stmt { kind: StmtKind::Error, span: self.span_from(start) };
        }
        self.stmt_depth += 1;
        let errors_before = self.error_count();
        let mut kind = self.stmt_kind();
        self.stmt_depth -= 1;
        // A simple statement with a syntax error is not analysed further: its pieces
        // would only produce follow-on errors.
        if self.error_count() > errors_before && is_simple(&kind) {
            kind = StmtKind::Error;
        }
        Stmt { kind, span: self.span_from(start) }
    }

    fn stmt_kind(&mut self) -> StmtKind {
        match self.nth(0) {
            T::Ident => self.stmt_starting_with_name(),
            T::Placeholder => self.placeholder_stmt(),
            T::Percent => self.late_call(),
            T::If => self.if_stmt(),
            T::For => self.for_stmt(),
            T::While => self.while_stmt(),
            T::Test => self.test_stmt(),
            T::Goto => {
                self.bump();
                let label = self.name();
                self.end_of_simple_stmt();
                StmtKind::Goto(label)
            }
            T::Return => {
                self.bump();
                let value = (!self.at(T::Semi)).then(|| self.expr());
                self.end_of_simple_stmt();
                StmtKind::Return(value)
            }
            T::Raise => {
                self.bump();
                let value = (!self.at(T::Semi)).then(|| self.expr());
                self.end_of_simple_stmt();
                StmtKind::Raise(value)
            }
            T::Retry => self.keyword_stmt(StmtKind::Retry),
            T::Trynext => self.keyword_stmt(StmtKind::TryNext),
            T::Exit => self.keyword_stmt(StmtKind::Exit),
            T::Connect => self.connect_stmt(),
            _ => {
                self.error_expected("an instruction");
                self.bump();
                self.recover_until(STMT_RECOVERY);
                self.eat(T::Semi);
                StmtKind::Error
            }
        }
    }

    fn keyword_stmt(&mut self, kind: StmtKind) -> StmtKind {
        self.bump();
        self.end_of_simple_stmt();
        kind
    }

    /// The `;` that ends a simple statement; on anything else, report and resync.
    pub(crate) fn end_of_simple_stmt(&mut self) {
        if self.expect_semi() {
            return;
        }
        self.recover_until(STMT_RECOVERY);
        self.eat(T::Semi);
    }

    /// Label `name:`, assignment `target := value;` or procedure call `name args;`.
    fn stmt_starting_with_name(&mut self) -> StmtKind {
        match self.nth(1) {
            T::Colon => {
                let label = self.name();
                self.bump();
                StmtKind::Label(label)
            }
            T::Assign | T::LBrace | T::Dot => self.assignment(),
            T::Eq => {
                // `x = 1;` is a common slip for `x := 1;`: say so, and read it as meant.
                let target = self.postfix_expr();
                let eq = self.bump();
                self.error(
                    SyntaxErrorKind::UnexpectedToken,
                    eq.span,
                    "`=` compares values; assignment is written `:=`".into(),
                );
                let value = self.expr();
                self.end_of_simple_stmt();
                StmtKind::Assign { target, value }
            }
            _ => {
                let name = self.name();
                let args = self.proc_args();
                StmtKind::Call { name, args }
            }
        }
    }

    fn assignment(&mut self) -> StmtKind {
        let target = self.postfix_expr();
        let value = if self.expect(T::Assign) {
            self.expr()
        } else {
            self.recover_until(STMT_RECOVERY);
            self.arena.alloc(ExprKind::Error, Span::default())
        };
        self.end_of_simple_stmt();
        StmtKind::Assign { target, value }
    }

    /// `<SMT>` (with or without `;`), or `<VAR> := value;`.
    fn placeholder_stmt(&mut self) -> StmtKind {
        let token = self.current();
        match Placeholder::from_text(token.span.text(self.text)) {
            Some(Placeholder::Var) if self.nth(1) == T::Assign => self.assignment(),
            Some(Placeholder::Smt) => {
                self.bump();
                self.eat(T::Semi);
                StmtKind::Placeholder(Placeholder::Smt)
            }
            _ => {
                self.bump();
                self.error(
                    SyntaxErrorKind::UnexpectedToken,
                    token.span,
                    "only <SMT> may stand for an instruction".into(),
                );
                self.eat(T::Semi);
                StmtKind::Error
            }
        }
    }

    /// `% expr % args;`
    fn late_call(&mut self) -> StmtKind {
        self.bump();
        let callee = self.expr();
        self.expect(T::Percent);
        let args = self.proc_args();
        StmtKind::LateCall { callee, args }
    }

    /// `IF c THEN ... ENDIF` or the compact `IF c stmt`.
    fn if_stmt(&mut self) -> StmtKind {
        let keyword = self.bump();
        let cond = self.expr();
        if !self.eat(T::Then) {
            return self.compact_if(cond);
        }
        let then = self.stmt_list();
        let mut elifs = Vec::new();
        let mut els = None;
        loop {
            match self.nth(0) {
                T::Elseif => {
                    let start = self.bump().span.start;
                    let cond = self.expr();
                    self.expect(T::Then);
                    let body = self.stmt_list();
                    elifs.push(ElseIf { cond: Some(cond), body, span: self.span_from(start) });
                }
                T::Placeholder if self.current().span.text(self.text) == "<EIT>" => {
                    let span = self.bump().span;
                    elifs.push(ElseIf { cond: None, body: Vec::new(), span });
                }
                T::Else if els.is_none() => {
                    self.bump();
                    els = Some(self.stmt_list());
                }
                _ => break,
            }
        }
        self.close_block(T::Endif, keyword.span, "IF");
        StmtKind::If { cond, then, elifs, els }
    }

    fn compact_if(&mut self, cond: crate::ast::ExprId) -> StmtKind {
        let token = self.current();
        if matches!(token.kind, T::If | T::For | T::While | T::Test) {
            self.error(
                SyntaxErrorKind::CompoundInCompactIf,
                token.span,
                "a compact IF (without THEN) takes one simple instruction; use IF ... THEN ... ENDIF".into(),
            );
        } else if STMT_LIST_END.contains(token.kind) || token.kind == T::Semi {
            self.error_expected("THEN or an instruction");
            self.eat(T::Semi);
            return StmtKind::Error;
        }
        let stmt = self.stmt();
        StmtKind::CompactIf { cond, stmt: Box::new(stmt) }
    }

    /// Consumes a block's END keyword or reports the block as unclosed at its opening.
    fn close_block(&mut self, end: T, opening: Span, what: &str) {
        if self.eat(end) {
            return;
        }
        let end_word = end.describe().trim_matches('`');
        self.error(SyntaxErrorKind::UnclosedBlock, opening, format!("{what} has no {end_word}"));
    }

    /// `FOR i FROM a TO b [STEP s] DO ... ENDFOR`.
    fn for_stmt(&mut self) -> StmtKind {
        let keyword = self.bump();
        let var = self.name();
        self.expect(T::From);
        let from = self.expr();
        self.expect(T::To);
        let to = self.expr();
        let step = self.eat(T::Step).then(|| self.expr());
        self.expect(T::Do);
        let body = self.stmt_list();
        self.close_block(T::Endfor, keyword.span, "FOR");
        StmtKind::For { var, from, to, step, body }
    }

    /// `WHILE c DO ... ENDWHILE`.
    fn while_stmt(&mut self) -> StmtKind {
        let keyword = self.bump();
        let cond = self.expr();
        self.expect(T::Do);
        let body = self.stmt_list();
        self.close_block(T::Endwhile, keyword.span, "WHILE");
        StmtKind::While { cond, body }
    }

    /// `TEST e {CASE v {, v} : ...} [DEFAULT : ...] ENDTEST`.
    fn test_stmt(&mut self) -> StmtKind {
        let keyword = self.bump();
        let subject = self.expr();
        let mut cases = Vec::new();
        let mut default = None;
        loop {
            match self.nth(0) {
                T::Case => {
                    let start = self.bump().span.start;
                    let mut values = vec![self.expr()];
                    while self.eat(T::Comma) {
                        values.push(self.expr());
                    }
                    self.expect(T::Colon);
                    let body = self.stmt_list();
                    cases.push(Case { values, body, span: self.span_from(start) });
                }
                T::Placeholder if self.current().span.text(self.text) == "<CSE>" => {
                    let span = self.bump().span;
                    cases.push(Case { values: Vec::new(), body: Vec::new(), span });
                }
                T::Default if default.is_none() => {
                    self.bump();
                    self.expect(T::Colon);
                    default = Some(self.stmt_list());
                }
                _ => break,
            }
        }
        self.close_block(T::Endtest, keyword.span, "TEST");
        StmtKind::Test { subject, cases, default }
    }

    /// `CONNECT target WITH trap;`
    fn connect_stmt(&mut self) -> StmtKind {
        self.bump();
        let target = self.postfix_expr();
        self.expect(T::With);
        let trap = self.name();
        self.end_of_simple_stmt();
        StmtKind::Connect { target, trap }
    }
}

fn is_simple(kind: &StmtKind) -> bool {
    !matches!(
        kind,
        StmtKind::If { .. }
            | StmtKind::CompactIf { .. }
            | StmtKind::For { .. }
            | StmtKind::While { .. }
            | StmtKind::Test { .. }
    )
}
