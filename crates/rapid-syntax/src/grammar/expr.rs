//! Expressions (§1.3): precedence exactly as §1.3.5, structure as the EBNF of §1.3.6.
//!
//! ```text
//! expr     ::= [NOT] lterm { (OR | XOR) lterm }
//! lterm    ::= relation { AND relation }
//! relation ::= simple [ relop simple ]
//! simple   ::= [+ | -] term { (+ | -) term }
//! term     ::= primary { (* | / | DIV | MOD) primary }
//! ```
//! The levels are parsed by one binding-power loop (`expr_bp`) over the table in
//! `infix_op`. Two tolerances the controller also has: NOT may open any logical term
//! (`a AND NOT b`), and a sign may open any primary (`a * -1`). Neither changes the
//! meaning of an expression the strict grammar accepts.

use crate::ast::{BinaryOp, ExprId, ExprKind, Placeholder, UnaryOp};
use crate::error::SyntaxErrorKind;
use crate::parser::{Parser, MAX_EXPR_DEPTH};
use crate::span::Span;
use crate::token::TokenKind as T;

/// Binding powers, lowest first: the levels of §1.3.5.
const OR_BP: u8 = 1;
const AND_BP: u8 = 2;
const REL_BP: u8 = 3;
const ADD_BP: u8 = 4;
const MUL_BP: u8 = 5;

/// The binary operator a token spells and its binding power.
#[rustfmt::skip]
fn infix_op(kind: T) -> Option<(BinaryOp, u8)> {
    Some(match kind {
        T::Or    => (BinaryOp::Or, OR_BP),     T::Xor => (BinaryOp::Xor, OR_BP),
        T::And   => (BinaryOp::And, AND_BP),
        T::Lt    => (BinaryOp::Lt, REL_BP),    T::Le  => (BinaryOp::Le, REL_BP),
        T::Eq    => (BinaryOp::Eq, REL_BP),    T::Gt  => (BinaryOp::Gt, REL_BP),
        T::Ge    => (BinaryOp::Ge, REL_BP),    T::Ne  => (BinaryOp::Ne, REL_BP),
        T::Plus  => (BinaryOp::Add, ADD_BP),   T::Minus => (BinaryOp::Sub, ADD_BP),
        T::Star  => (BinaryOp::Mul, MUL_BP),   T::Slash => (BinaryOp::Div, MUL_BP),
        T::Div   => (BinaryOp::IntDiv, MUL_BP), T::Mod => (BinaryOp::Mod, MUL_BP),
        _ => return None,
    })
}

impl Parser<'_, '_, '_> {
    /// A full expression.
    pub(crate) fn expr(&mut self) -> ExprId {
        self.expr_bp(OR_BP)
    }

    /// Operators binding at least as tightly as `min_bp`, left to right. Relations
    /// do not chain: `a < b < c` is reported.
    fn expr_bp(&mut self, min_bp: u8) -> ExprId {
        let start = self.current().span.start;
        if self.expr_depth >= MAX_EXPR_DEPTH {
            return self.too_deep(start);
        }
        self.expr_depth += 1;
        let depth_on_entry = self.expr_depth;
        let mut lhs = self.prefix();
        let mut lhs_is_relation = false;
        while let Some((op, bp)) = infix_op(self.nth(0)) {
            if bp < min_bp {
                break;
            }
            // Each operator in a chain nests the tree one level deeper on the left;
            // later passes walk it recursively, so the chain counts towards the limit.
            if self.expr_depth + 1 >= MAX_EXPR_DEPTH {
                let span = self.current().span;
                self.error(
                    SyntaxErrorKind::NestingTooDeep,
                    span,
                    format!(
                        "an expression with more than {MAX_EXPR_DEPTH} operators in a chain is too complex; split it"
                    ),
                );
                self.skip_expression_rest();
                break;
            }
            self.expr_depth += 1;
            let op_token = self.bump();
            if bp == REL_BP && lhs_is_relation {
                self.error(
                    SyntaxErrorKind::UnexpectedToken,
                    op_token.span,
                    "comparisons do not chain: write `a < b AND b < c`".into(),
                );
            }
            let rhs = self.expr_bp(bp + 1);
            lhs = self.binary(op, lhs, rhs);
            lhs_is_relation = bp == REL_BP;
        }
        self.expr_depth = depth_on_entry - 1;
        lhs
    }

    /// `NOT` takes a logical term (`NOT a AND b` is `NOT (a AND b)`, per the EBNF);
    /// a sign takes a term (`-a*b` is `-(a*b)`). NOT may also open a later logical
    /// term (`a AND NOT b`) and a sign any primary (`a * -1`), as the controller
    /// accepts; neither changes the meaning of what the strict grammar accepts.
    fn prefix(&mut self) -> ExprId {
        let (op, operand_bp) = match self.nth(0) {
            T::Not => (UnaryOp::Not, AND_BP),
            T::Minus => (UnaryOp::Neg, MUL_BP),
            T::Plus => (UnaryOp::Plus, MUL_BP),
            _ => return self.primary(),
        };
        let start = self.bump().span.start;
        let operand = self.expr_bp(operand_bp);
        self.arena.alloc(ExprKind::Unary { op, operand }, self.span_from(start))
    }

    /// Skips the rest of an expression that is too complex: operators and operands
    /// (brackets skipped whole) up to whatever cannot continue an expression.
    fn skip_expression_rest(&mut self) {
        loop {
            match self.nth(0) {
                T::LParen | T::LBracket | T::LBrace => self.skip_nested(),
                kind if infix_op(kind).is_some()
                    || matches!(
                        kind,
                        T::Not | T::Num | T::Str | T::Ident | T::True | T::False | T::Dot | T::Placeholder
                    ) =>
                {
                    self.bump();
                }
                _ => return,
            }
        }
    }

    /// Reports nesting past the limit once and skips the construct without recursing.
    fn too_deep(&mut self, start: u32) -> ExprId {
        self.error_too_deep("expressions", MAX_EXPR_DEPTH);
        while matches!(self.nth(0), T::Minus | T::Plus | T::Not) {
            self.bump();
        }
        self.skip_nested();
        self.arena.alloc(ExprKind::Error, self.span_from(start))
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
            T::Ident if self.nth(1) == T::LParen => {
                let call = self.call();
                self.refuse_selectors_of_a_result();
                call
            }
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

    /// `f(x).comp` or `f(x){i}`: RAPID selects components and elements of data only
    /// (a variable, persistent, constant or parameter), never of a function's result.
    /// Said plainly, and the selectors are read over so the expression goes on.
    fn refuse_selectors_of_a_result(&mut self) {
        if !matches!(self.nth(0), T::Dot | T::LBrace) {
            return;
        }
        let span = self.current().span;
        let message = "a component or element of a function's result cannot be selected: assign the result to a \
                       variable first";
        self.error(SyntaxErrorKind::UnexpectedToken, span, message.to_owned());
        loop {
            match self.nth(0) {
                T::Dot => {
                    self.bump();
                    self.name();
                }
                T::LBrace => {
                    self.bump();
                    self.expr_list(T::RBrace);
                }
                _ => return,
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
        let mut chain = 0;
        loop {
            if matches!(self.nth(0), T::LBrace | T::Dot) && self.expr_depth + chain >= MAX_EXPR_DEPTH {
                let span = self.current().span;
                self.error(
                    SyntaxErrorKind::NestingTooDeep,
                    span,
                    format!("more than {MAX_EXPR_DEPTH} nested indices and components; simplify the reference"),
                );
                self.skip_expression_rest();
                return expr;
            }
            chain += 1;
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
        let start = self.current().span.start;
        if self.expr_depth >= MAX_EXPR_DEPTH {
            return self.too_deep(start);
        }
        self.bump();
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
