//! Expressions (§1.3): precedence exactly as §1.3.5, structure as the EBNF of §1.3.6.
//!
//! ```text
//! expr     ::= [NOT] lterm { (OR | XOR) lterm }
//! lterm    ::= relation { AND relation }
//! relation ::= simple [ relop simple ]
//! simple   ::= [+ | -] term { (+ | -) term }
//! term     ::= primary { (* | / | DIV | MOD) primary }
//! ```
//! Two tolerances the controller also has: NOT may open any logical term
//! (`a AND NOT b`), and a sign may open any primary (`a * -1`). Neither changes the
//! meaning of an expression the strict grammar accepts.

use crate::ast::{BinaryOp, ExprId, ExprKind, Placeholder, UnaryOp};
use crate::error::SyntaxErrorKind;
use crate::parser::{Parser, MAX_EXPR_DEPTH};
use crate::span::Span;
use crate::token::TokenKind as T;

impl Parser<'_, '_, '_> {
    /// A full expression.
    pub(crate) fn expr(&mut self) -> ExprId {
        let start = self.current().span.start;
        if self.expr_depth >= MAX_EXPR_DEPTH {
            self.error_too_deep("expressions", MAX_EXPR_DEPTH);
            self.skip_nested();
            return self.arena.alloc(ExprKind::Error, self.span_from(start));
        }
        self.expr_depth += 1;
        let mut lhs = self.not_or_lterm();
        loop {
            let op = match self.nth(0) {
                T::Or => BinaryOp::Or,
                T::Xor => BinaryOp::Xor,
                _ => break,
            };
            self.bump();
            let rhs = self.not_or_lterm();
            lhs = self.binary(op, lhs, rhs);
        }
        self.expr_depth -= 1;
        lhs
    }

    fn not_or_lterm(&mut self) -> ExprId {
        if !self.at(T::Not) {
            return self.lterm();
        }
        let start = self.bump().span.start;
        let operand = self.lterm();
        self.arena.alloc(ExprKind::Unary { op: UnaryOp::Not, operand }, self.span_from(start))
    }

    fn lterm(&mut self) -> ExprId {
        let mut lhs = self.relation();
        while self.eat(T::And) {
            let rhs = if self.at(T::Not) { self.not_or_lterm() } else { self.relation() };
            lhs = self.binary(BinaryOp::And, lhs, rhs);
        }
        lhs
    }

    fn relation(&mut self) -> ExprId {
        let lhs = self.simple();
        let Some(op) = relop(self.nth(0)) else { return lhs };
        self.bump();
        let rhs = self.simple();
        let mut res = self.binary(op, lhs, rhs);
        if let Some(op) = relop(self.nth(0)) {
            let span = self.bump().span;
            self.error(SyntaxErrorKind::UnexpectedToken, span, "comparisons do not chain: write `a < b AND b < c`".into());
            let rhs = self.simple();
            res = self.binary(op, res, rhs);
        }
        res
    }

    fn simple(&mut self) -> ExprId {
        let mut lhs = match self.nth(0) {
            T::Minus | T::Plus => self.signed_term(),
            _ => self.term(),
        };
        loop {
            let op = match self.nth(0) {
                T::Plus => BinaryOp::Add,
                T::Minus => BinaryOp::Sub,
                _ => break,
            };
            self.bump();
            let rhs = self.term();
            lhs = self.binary(op, lhs, rhs);
        }
        lhs
    }

    fn term(&mut self) -> ExprId {
        let mut lhs = self.signed();
        loop {
            let op = match self.nth(0) {
                T::Star => BinaryOp::Mul,
                T::Slash => BinaryOp::Div,
                T::Div => BinaryOp::IntDiv,
                T::Mod => BinaryOp::Mod,
                _ => break,
            };
            self.bump();
            let rhs = self.signed();
            lhs = self.binary(op, lhs, rhs);
        }
        lhs
    }

    /// `[+|-] term` at the start of a simple expression: the sign covers the whole
    /// term (`-a*b` is `-(a*b)`).
    fn signed_term(&mut self) -> ExprId {
        let op = if self.bump().kind == T::Minus { UnaryOp::Neg } else { UnaryOp::Plus };
        let start = self.prev_end() - 1;
        let operand = self.term();
        self.arena.alloc(ExprKind::Unary { op, operand }, self.span_from(start))
    }

    /// A primary, optionally signed (the tolerance `a * -1`).
    fn signed(&mut self) -> ExprId {
        let op = match self.nth(0) {
            T::Minus => UnaryOp::Neg,
            T::Plus => UnaryOp::Plus,
            _ => return self.primary(),
        };
        let start = self.bump().span.start;
        if self.expr_depth >= MAX_EXPR_DEPTH {
            self.error_too_deep("expressions", MAX_EXPR_DEPTH);
            while matches!(self.nth(0), T::Minus | T::Plus) {
                self.bump();
            }
            self.skip_nested();
            return self.arena.alloc(ExprKind::Error, self.span_from(start));
        }
        self.expr_depth += 1;
        let operand = self.signed();
        self.expr_depth -= 1;
        self.arena.alloc(ExprKind::Unary { op, operand }, self.span_from(start))
    }

    fn binary(&mut self, op: BinaryOp, lhs: ExprId, rhs: ExprId) -> ExprId {
        let span = self.arena.expr(lhs).span.cover(self.arena.expr(rhs).span);
        self.arena.alloc(ExprKind::Binary { op, lhs, rhs }, span)
    }

    fn primary(&mut self) -> ExprId {
        let token = self.current();
        match token.kind {
            T::Num => self.leaf(ExprKind::Num),
            T::Str => self.leaf(ExprKind::Str),
            T::True => self.leaf(ExprKind::Bool(true)),
            T::False => self.leaf(ExprKind::Bool(false)),
            T::Ident if self.nth(1) == T::LParen => self.call(),
            T::Ident => self.postfix_expr(),
            T::LParen => {
                self.bump();
                let inner = self.expr();
                self.expect(T::RParen);
                self.arena.alloc(ExprKind::Paren(inner), self.span_from(token.span.start))
            }
            T::LBracket => self.aggregate(),
            T::Placeholder => match Placeholder::from_text(token.span.text(self.text)) {
                Some(Placeholder::Var | Placeholder::Id) => self.postfix_expr(),
                Some(ph) => self.leaf(ExprKind::Placeholder(ph)),
                None => self.leaf(ExprKind::Error),
            },
            _ => {
                self.error_expected("an expression");
                self.arena.alloc(ExprKind::Error, Span { start: token.span.start, end: token.span.start })
            }
        }
    }

    fn leaf(&mut self, kind: ExprKind) -> ExprId {
        let token = self.bump();
        self.arena.alloc(kind, token.span)
    }

    /// A data reference: `name`, `name{i, j}`, `name.comp`, and combinations.
    pub(crate) fn postfix_expr(&mut self) -> ExprId {
        let token = self.current();
        let mut expr = match token.kind {
            T::Placeholder => {
                self.bump();
                let ph = Placeholder::from_text(token.span.text(self.text)).unwrap_or(Placeholder::Var);
                self.arena.alloc(ExprKind::Placeholder(ph), token.span)
            }
            _ => {
                let name = self.name();
                self.arena.alloc(ExprKind::Name(name.sym), name.span)
            }
        };
        loop {
            match self.nth(0) {
                T::LBrace => {
                    self.bump();
                    let indices = self.expr_list(T::RBrace);
                    let span = self.span_from(token.span.start);
                    expr = self.arena.alloc(ExprKind::Index { base: expr, indices }, span);
                }
                T::Dot => {
                    self.bump();
                    let field = self.name();
                    let span = self.span_from(token.span.start);
                    expr = self.arena.alloc(ExprKind::Field { base: expr, field: field.sym }, span);
                }
                _ => return expr,
            }
        }
    }

    /// `[e1, e2, ...]`.
    fn aggregate(&mut self) -> ExprId {
        let start = self.bump().span.start;
        if self.expr_depth >= MAX_EXPR_DEPTH {
            self.error_too_deep("expressions", MAX_EXPR_DEPTH);
            self.skip_nested();
            return self.arena.alloc(ExprKind::Error, self.span_from(start));
        }
        self.expr_depth += 1;
        let items = self.expr_list(T::RBracket);
        self.expr_depth -= 1;
        self.arena.alloc(ExprKind::Aggregate(items), self.span_from(start))
    }

    /// `e {, e} close`, after the opening bracket.
    fn expr_list(&mut self, close: T) -> crate::ast::ListRange {
        let mark = self.scratch_exprs.len();
        loop {
            let item = self.expr();
            self.scratch_exprs.push(item);
            if !self.eat(T::Comma) {
                break;
            }
        }
        if !self.eat(close) {
            self.error_expected(close.describe());
            self.recover_until(crate::token::TokenSet::new(&[close, T::Semi]).union(super::STMT_LIST_END));
            self.eat(close);
        }
        let items = self.arena.alloc_list(&self.scratch_exprs[mark..]);
        self.scratch_exprs.truncate(mark);
        items
    }
}

fn relop(kind: T) -> Option<BinaryOp> {
    Some(match kind {
        T::Lt => BinaryOp::Lt,
        T::Le => BinaryOp::Le,
        T::Eq => BinaryOp::Eq,
        T::Gt => BinaryOp::Gt,
        T::Ge => BinaryOp::Ge,
        T::Ne => BinaryOp::Ne,
        _ => return None,
    })
}
