//! Kernels: num assignments and num conditions compiled a second time into a
//! straight-line f32 program (`ir::Kernel`) that the executor runs without touching
//! the value stack. The statement's general code always follows its kernel and runs
//! whenever the kernel cannot (an operand that is not a plain num at run time, or an
//! error such as a division by zero), so a kernel never changes what a program does;
//! it only skips the general code when the answer is certain.
//!
//! Only expressions whose every leaf is num data (locals, module data, elements of
//! one-dimensional num arrays) or a num literal qualify, with at least one operator.

use rapid_sema::symbols::DataKind;
use rapid_sema::types::TypeId;
use rapid_syntax::ast::{Arena, BinaryOp, ExprId, ExprKind, ParamMode, UnaryOp};
use rapid_syntax::literal::num_value;

use super::{LocalKind, Resolved, RoutineCompiler};
use crate::ir::{Instr, Kernel, KernelOp, KernelOperand, KernelTarget, KERNEL_DEPTH};

/// What a kernel sub-expression gives.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Num,
    Bool,
}

impl RoutineCompiler<'_> {
    /// Emits a `KernelStore` for `target := value` when both qualify; returns the
    /// instruction so its `skip` can be pointed past the general code.
    pub(crate) fn kernel_store(&mut self, arena: &Arena, target: ExprId, value: ExprId) -> Option<u32> {
        if !has_operator(arena, value) && !is_element(arena, value) && !is_element(arena, target) {
            return None;
        }
        let mut ops = Vec::new();
        let target = self.kernel_target(arena, target, &mut ops)?;
        self.kernel_expr(arena, value, Kind::Num, &mut ops)?;
        self.emit_kernel(Kernel { ops, target: Some(target) }, |kernel| Instr::KernelStore { kernel, skip: 0 })
    }

    /// Emits a `KernelBranch` for condition `cond` when it qualifies.
    pub(crate) fn kernel_branch(&mut self, arena: &Arena, cond: ExprId) -> Option<u32> {
        let mut ops = Vec::new();
        self.kernel_expr(arena, cond, Kind::Bool, &mut ops)?;
        self.emit_kernel(Kernel { ops, target: None }, |kernel| Instr::KernelBranch { kernel, on_false: 0, skip: 0 })
    }

    /// Emits a `KernelReturn` for `RETURN value` in a FUNC returning num, when the
    /// value qualifies (a bare leaf too: the return then skips a push and a pop).
    pub(crate) fn kernel_return(&mut self, arena: &Arena, value: ExprId) -> Option<u32> {
        if !self.is_num(self.st.ret_ty?) {
            return None;
        }
        let mut ops = Vec::new();
        self.kernel_expr(arena, value, Kind::Num, &mut ops)?;
        self.emit_kernel(Kernel { ops, target: None }, |kernel| Instr::KernelReturn { kernel })
    }

    fn emit_kernel(&mut self, mut kernel: Kernel, instr: impl FnOnce(u32) -> Instr) -> Option<u32> {
        if max_depth(&kernel.ops)? > KERNEL_DEPTH {
            return None;
        }
        let ops: Vec<KernelOp> = fuse_operands(&kernel.ops).into_iter().map(specialize).collect();
        kernel.ops = fuse_elements(&ops);
        self.st.code.kernels.push(kernel);
        let idx = self.st.code.kernels.len() as u32 - 1;
        Some(self.st.code.emit(instr(idx)))
    }

    /// A num variable the kernel may write: a local (or a parameter, through its
    /// reference at run time), a module-level VAR, or an element of a
    /// one-dimensional num VAR array (its index computed first). Persistents are left
    /// to the general code.
    fn kernel_target(&self, arena: &Arena, target: ExprId, ops: &mut Vec<KernelOp>) -> Option<KernelTarget> {
        match arena.expr(target).kind {
            ExprKind::Name(_) => match self.name(target)? {
                Resolved::Local(local) if self.is_num(local.ty) && local.rank == 0 => {
                    (!matches!(local.kind, LocalKind::Param { mode: ParamMode::Pers, .. }))
                        .then_some(KernelTarget::Local(local.slot))
                }
                Resolved::Global(idx) => {
                    let data = self.prog.data(idx)?;
                    (data.kind == DataKind::Var && data.rank == 0 && self.is_num(data.ty))
                        .then_some(KernelTarget::Global(idx))
                }
                _ => None,
            },
            ExprKind::Index { base, indices } => {
                let (global, slot) = self.num_array_1d(arena, base, true)?;
                let [index] = arena.list(indices) else { return None };
                self.kernel_expr(arena, *index, Kind::Num, ops)?;
                Some(KernelTarget::Elem { global, slot })
            }
            _ => None,
        }
    }

    /// Appends the ops of `id`, which must give `want`; `None` when it does not qualify.
    fn kernel_expr(&self, arena: &Arena, id: ExprId, want: Kind, ops: &mut Vec<KernelOp>) -> Option<()> {
        let expr = *arena.expr(id);
        match (expr.kind, want) {
            (ExprKind::Num, Kind::Num) => {
                let value = num_value(expr.span.text(self.text))?;
                ops.push(KernelOp::Const(value as f32));
            }
            (ExprKind::Name(_), Kind::Num) => ops.push(self.kernel_leaf(id)?),
            (ExprKind::Index { base, indices }, Kind::Num) => {
                let (global, slot) = self.num_array_1d(arena, base, false)?;
                let [index] = arena.list(indices) else { return None };
                self.kernel_expr(arena, *index, Kind::Num, ops)?;
                ops.push(KernelOp::Elem { global, slot });
            }
            (ExprKind::Paren(inner), _) => self.kernel_expr(arena, inner, want, ops)?,
            (ExprKind::Unary { op: UnaryOp::Plus, operand }, Kind::Num) => {
                self.kernel_expr(arena, operand, Kind::Num, ops)?;
            }
            (ExprKind::Unary { op: UnaryOp::Neg, operand }, Kind::Num) => {
                self.kernel_expr(arena, operand, Kind::Num, ops)?;
                ops.push(KernelOp::Neg);
            }
            (ExprKind::Unary { op: UnaryOp::Not, operand }, Kind::Bool) => {
                self.kernel_expr(arena, operand, Kind::Bool, ops)?;
                ops.push(KernelOp::Not);
            }
            (ExprKind::Binary { op, lhs, rhs }, _) => {
                let operands = operand_kind(op)?;
                if result_kind(op) != want {
                    return None;
                }
                self.kernel_expr(arena, lhs, operands, ops)?;
                self.kernel_expr(arena, rhs, operands, ops)?;
                ops.push(KernelOp::Binary(op));
            }
            _ => return None,
        }
        Some(())
    }

    /// A num datum read by name.
    fn kernel_leaf(&self, id: ExprId) -> Option<KernelOp> {
        match self.name(id)? {
            Resolved::Local(local) if self.is_num(local.ty) && local.rank == 0 => Some(KernelOp::Local(local.slot)),
            Resolved::Global(idx) => {
                let data = self.prog.data(idx)?;
                (data.rank == 0
                    && self.is_num(data.ty)
                    && matches!(data.kind, DataKind::Var | DataKind::Pers | DataKind::Const))
                .then_some(KernelOp::Global(idx))
            }
            _ => None,
        }
    }

    /// A one-dimensional num array named directly: (global?, slot). For writes, module
    /// data must be a VAR.
    fn num_array_1d(&self, arena: &Arena, base: ExprId, write: bool) -> Option<(bool, u32)> {
        let ExprKind::Name(_) = arena.expr(base).kind else { return None };
        match self.name(base)? {
            Resolved::Local(local) => (self.is_num(local.ty) && local.rank == 1).then_some((false, local.slot)),
            Resolved::Global(idx) => {
                let data = self.prog.data(idx)?;
                let kind_ok = if write { data.kind == DataKind::Var } else { data.kind != DataKind::LoopVar };
                (kind_ok && data.rank == 1 && self.is_num(data.ty)).then_some((true, idx))
            }
            _ => None,
        }
    }

    /// num itself or an alias of it (never dnum).
    fn is_num(&self, ty: TypeId) -> bool {
        self.prog.types.canonical(ty) == self.prog.core.num
    }
}

/// What the operands of `op` must be.
fn operand_kind(op: BinaryOp) -> Option<Kind> {
    use BinaryOp as B;
    match op {
        B::Add | B::Sub | B::Mul | B::Div | B::IntDiv | B::Mod => Some(Kind::Num),
        B::Lt | B::Le | B::Gt | B::Ge | B::Eq | B::Ne => Some(Kind::Num),
        B::And | B::Or | B::Xor => Some(Kind::Bool),
    }
}

fn result_kind(op: BinaryOp) -> Kind {
    use BinaryOp as B;
    match op {
        B::Add | B::Sub | B::Mul | B::Div | B::IntDiv | B::Mod => Kind::Num,
        _ => Kind::Bool,
    }
}

/// An assignment of a bare scalar leaf to a scalar gains little from a kernel.
fn has_operator(arena: &Arena, id: ExprId) -> bool {
    match arena.expr(id).kind {
        ExprKind::Paren(inner) => has_operator(arena, inner),
        ExprKind::Binary { .. } | ExprKind::Unary { .. } => true,
        _ => false,
    }
}

/// An element of an array: its general code takes three or four instructions
/// (index, value, `LoadElem`/`StoreElem`), so even a plain copy such as a swap's
/// `a{j} := a{j + 1}` gains from a kernel (bench/interp bubble).
fn is_element(arena: &Arena, id: ExprId) -> bool {
    match arena.expr(id).kind {
        ExprKind::Paren(inner) => is_element(arena, inner),
        ExprKind::Index { .. } => true,
        _ => false,
    }
}

/// The most values the ops hold at once; `None` for a malformed sequence.
/// Fuses each operand push that a binary operation consumes at once into that
/// operation (`Local(j), Binary(+)` → `BinaryWith(+, Local(j))`): same results, one
/// dispatch instead of two.
fn fuse_operands(ops: &[KernelOp]) -> Vec<KernelOp> {
    let mut out = Vec::with_capacity(ops.len());
    let mut i = 0;
    while i < ops.len() {
        let operand = match ops[i] {
            KernelOp::Local(slot) => Some(KernelOperand::Local(slot)),
            KernelOp::Global(idx) => Some(KernelOperand::Global(idx)),
            KernelOp::Const(n) => Some(KernelOperand::Const(n)),
            _ => None,
        };
        // The first op pushes the first operand: only a later push can be fused.
        match (operand, ops.get(i + 1)) {
            (Some(operand), Some(&KernelOp::Binary(op))) if !out.is_empty() => {
                out.push(KernelOp::BinaryWith(op, operand));
                i += 2;
            }
            _ => {
                out.push(ops[i]);
                i += 1;
            }
        }
    }
    out
}

/// Fuses each element read whose index is a local, or a local plus a constant, into
/// one `ElemAt` (see `KernelOp`). Same results: a non-finite index, which `AddConst`
/// would refuse, is no element either.
fn fuse_elements(ops: &[KernelOp]) -> Vec<KernelOp> {
    let mut out = Vec::with_capacity(ops.len());
    let mut i = 0;
    while i < ops.len() {
        let fused = match ops[i..] {
            [KernelOp::Local(index), KernelOp::Elem { global, slot }, ..] => Some((2, index, 0.0, global, slot)),
            [KernelOp::Local(index), KernelOp::AddConst(offset), KernelOp::Elem { global, slot }, ..] => {
                Some((3, index, offset, global, slot))
            }
            _ => None,
        };
        match fused {
            Some((len, index, offset, global, slot)) => {
                out.push(KernelOp::ElemAt { global, slot, index, offset });
                i += len;
            }
            None => {
                out.push(ops[i]);
                i += 1;
            }
        }
    }
    out
}

/// The specialised form of a fused operation, when there is one (see `KernelOp`).
fn specialize(op: KernelOp) -> KernelOp {
    use rapid_syntax::ast::BinaryOp as B;
    match op {
        KernelOp::BinaryWith(B::Add, KernelOperand::Const(c)) => KernelOp::AddConst(c),
        KernelOp::BinaryWith(B::Sub, KernelOperand::Const(c)) => KernelOp::SubConst(c),
        KernelOp::BinaryWith(B::Mul, KernelOperand::Const(c)) => KernelOp::MulConst(c),
        KernelOp::BinaryWith(B::Mod, KernelOperand::Const(c)) => KernelOp::ModConst(c),
        KernelOp::BinaryWith(B::Add, KernelOperand::Local(slot)) => KernelOp::AddLocal(slot),
        KernelOp::BinaryWith(B::Lt, KernelOperand::Const(c)) => KernelOp::LtConst(c),
        KernelOp::BinaryWith(B::Gt, KernelOperand::Const(c)) => KernelOp::GtConst(c),
        other => other,
    }
}

fn max_depth(ops: &[KernelOp]) -> Option<usize> {
    let (mut depth, mut max) = (0usize, 0usize);
    for op in ops {
        match op {
            KernelOp::Local(_) | KernelOp::Global(_) | KernelOp::Const(_) | KernelOp::ElemAt { .. } => depth += 1,
            KernelOp::Elem { .. }
            | KernelOp::Neg
            | KernelOp::Not
            | KernelOp::BinaryWith(..)
            | KernelOp::AddConst(_)
            | KernelOp::SubConst(_)
            | KernelOp::MulConst(_)
            | KernelOp::ModConst(_)
            | KernelOp::AddLocal(_)
            | KernelOp::LtConst(_)
            | KernelOp::GtConst(_) => depth.checked_sub(1).map(|_| ())?,
            KernelOp::Binary(_) => depth = depth.checked_sub(1)?,
        }
        max = max.max(depth);
    }
    Some(max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_syntax::ast::BinaryOp::{Add, Mul};

    #[test]
    fn common_fused_operations_get_their_own_op() {
        use rapid_syntax::ast::BinaryOp::{Div, Gt, Lt, Mod, Sub};
        let with = |op, operand| specialize(KernelOp::BinaryWith(op, operand));
        assert_eq!(with(Add, KernelOperand::Const(2.0)), KernelOp::AddConst(2.0));
        assert_eq!(with(Sub, KernelOperand::Const(2.0)), KernelOp::SubConst(2.0));
        assert_eq!(with(Mul, KernelOperand::Const(7.0)), KernelOp::MulConst(7.0));
        assert_eq!(with(Mod, KernelOperand::Const(9.0)), KernelOp::ModConst(9.0));
        assert_eq!(with(Add, KernelOperand::Local(1)), KernelOp::AddLocal(1));
        assert_eq!(with(Lt, KernelOperand::Const(2.0)), KernelOp::LtConst(2.0));
        assert_eq!(with(Gt, KernelOperand::Const(76.0)), KernelOp::GtConst(76.0));
        // The others stay general.
        let general = KernelOp::BinaryWith(Div, KernelOperand::Const(4.0));
        assert_eq!(specialize(general), general);
        let general = KernelOp::BinaryWith(Sub, KernelOperand::Local(1));
        assert_eq!(specialize(general), general);
        assert_eq!(specialize(KernelOp::Local(0)), KernelOp::Local(0));
    }

    #[test]
    fn element_reads_indexed_by_a_local_fuse() {
        use rapid_syntax::ast::BinaryOp::Gt;
        // a{j} > a{j + 1}
        let ops = [
            KernelOp::Local(9),
            KernelOp::Elem { global: true, slot: 4 },
            KernelOp::Local(9),
            KernelOp::AddConst(1.0),
            KernelOp::Elem { global: true, slot: 4 },
            KernelOp::Binary(Gt),
        ];
        assert_eq!(
            fuse_elements(&ops),
            [
                KernelOp::ElemAt { global: true, slot: 4, index: 9, offset: 0.0 },
                KernelOp::ElemAt { global: true, slot: 4, index: 9, offset: 1.0 },
                KernelOp::Binary(Gt),
            ]
        );
        // An index computed otherwise stays as it is.
        let ops = [KernelOp::Local(1), KernelOp::MulConst(2.0), KernelOp::Elem { global: false, slot: 0 }];
        assert_eq!(fuse_elements(&ops), ops);
    }

    #[test]
    fn operand_pushes_fuse_into_the_operation_that_takes_them() {
        // acc * 7 + j: the first operand stays a push, the others are read in place.
        let ops = [
            KernelOp::Local(0),
            KernelOp::Const(7.0),
            KernelOp::Binary(Mul),
            KernelOp::Local(1),
            KernelOp::Binary(Add),
        ];
        assert_eq!(
            fuse_operands(&ops),
            [
                KernelOp::Local(0),
                KernelOp::BinaryWith(Mul, KernelOperand::Const(7.0)),
                KernelOp::BinaryWith(Add, KernelOperand::Local(1)),
            ]
        );
        // An index pushed for an element read is not an operand: nothing fuses.
        let ops =
            [KernelOp::Global(3), KernelOp::Local(1), KernelOp::Elem { global: true, slot: 2 }, KernelOp::Binary(Add)];
        assert_eq!(fuse_operands(&ops), ops);
        // (a + b) * (c + d): the second group's first push stays.
        let ops = [
            KernelOp::Local(0),
            KernelOp::Local(1),
            KernelOp::Binary(Add),
            KernelOp::Local(2),
            KernelOp::Local(3),
            KernelOp::Binary(Add),
            KernelOp::Binary(Mul),
        ];
        assert_eq!(
            fuse_operands(&ops),
            [
                KernelOp::Local(0),
                KernelOp::BinaryWith(Add, KernelOperand::Local(1)),
                KernelOp::Local(2),
                KernelOp::BinaryWith(Add, KernelOperand::Local(3)),
                KernelOp::Binary(Mul),
            ]
        );
        assert_eq!(max_depth(&fuse_operands(&ops)), Some(2));
    }
}
