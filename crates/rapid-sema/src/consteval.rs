//! Constant and literal expressions (§1.2.2 "启动数据"): which expressions qualify, and
//! the value of numeric constant expressions (for array dimensions).

use rapid_syntax::ast::{Arena, BinaryOp, ExprId, ExprKind, UnaryOp};
use rapid_syntax::literal::num_value;

use crate::checker::Checker;
use crate::symbols::{DataKind, Def};

impl Checker<'_> {
    /// The value of a numeric constant expression, if it has one.
    pub(crate) fn const_num(&self, arena: &Arena, id: ExprId) -> Option<f64> {
        let expr = arena.expr(id);
        match expr.kind {
            ExprKind::Num => num_value(self.text(expr.span)),
            ExprKind::Paren(inner) => self.const_num(arena, inner),
            ExprKind::Name(sym) => match self.lookup(sym) {
                Some(Def::Data(data)) if self.data(data).kind == DataKind::Const => self.data(data).const_value,
                _ => None,
            },
            ExprKind::Unary { op: UnaryOp::Neg, operand } => self.const_num(arena, operand).map(|v| -v),
            ExprKind::Unary { op: UnaryOp::Plus, operand } => self.const_num(arena, operand),
            ExprKind::Binary { op, lhs, rhs } => {
                let (a, b) = (self.const_num(arena, lhs)?, self.const_num(arena, rhs)?);
                match op {
                    BinaryOp::Add => Some(a + b),
                    BinaryOp::Sub => Some(a - b),
                    BinaryOp::Mul => Some(a * b),
                    BinaryOp::Div if b != 0.0 => Some(a / b),
                    BinaryOp::IntDiv if b != 0.0 => Some((a / b).trunc()),
                    BinaryOp::Mod if b != 0.0 => Some(a % b),
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// A constant expression: literals, constants and operators on them. Function
    /// calls, variables and persistents are not constant.
    pub(crate) fn is_constant(&self, arena: &Arena, id: ExprId) -> bool {
        match arena.expr(id).kind {
            ExprKind::Num | ExprKind::Str | ExprKind::Bool(_) | ExprKind::Placeholder(_) | ExprKind::Error => true,
            ExprKind::Name(sym) => match self.lookup(sym) {
                Some(Def::Data(data)) => self.data(data).kind == DataKind::Const,
                // Undefined names are reported elsewhere.
                None => true,
                _ => false,
            },
            ExprKind::Index { base, indices } => {
                self.is_constant(arena, base) && arena.list(indices).iter().all(|&i| self.is_constant(arena, i))
            }
            ExprKind::Field { base, .. } | ExprKind::Paren(base) | ExprKind::Unary { operand: base, .. } => {
                self.is_constant(arena, base)
            }
            ExprKind::Binary { lhs, rhs, .. } => self.is_constant(arena, lhs) && self.is_constant(arena, rhs),
            ExprKind::Aggregate(items) => arena.list(items).iter().all(|&i| self.is_constant(arena, i)),
            ExprKind::Call { .. } => false,
        }
    }

    /// A literal expression: literals, signed num literals and aggregates of them.
    pub(crate) fn is_literal(&self, arena: &Arena, id: ExprId) -> bool {
        match arena.expr(id).kind {
            ExprKind::Num | ExprKind::Str | ExprKind::Bool(_) | ExprKind::Placeholder(_) | ExprKind::Error => true,
            ExprKind::Unary { op: UnaryOp::Neg | UnaryOp::Plus, operand } => {
                matches!(arena.expr(operand).kind, ExprKind::Num)
            }
            ExprKind::Aggregate(items) => arena.list(items).iter().all(|&i| self.is_literal(arena, i)),
            _ => false,
        }
    }
}
