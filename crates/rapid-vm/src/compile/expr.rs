//! Expressions (§1.3): literals, data references as places, aggregates typed from the
//! expected type, function calls, operators.

use rapid_sema::types::{Atomic, TypeId, TypeKind};
use rapid_sema::ExprType;
use rapid_syntax::ast::{Arena, ExprId, ExprKind, UnaryOp};
use rapid_syntax::literal::{num_value, string_value};

use super::{CompileError, Resolved, RoutineCompiler};
use crate::ir::{Instr, Operand};
use crate::packed::{Builder, Whole};
use crate::value::Value;

/// How far a routine's code and constants reach at some point of compiling it.
#[derive(Debug, Clone, Copy)]
struct Mark {
    instrs: usize,
    consts: usize,
    packed: usize,
}

/// The type (and known dimension sizes) the context expects.
pub(crate) type Expected = Option<(TypeId, [u32; 3])>;

impl RoutineCompiler<'_> {
    /// Emits code that pushes the value of `id`.
    pub(crate) fn expr(&mut self, arena: &Arena, id: ExprId, expect: Expected) -> Result<(), CompileError> {
        let expr = *arena.expr(id);
        if !self.st.signal_as_data
            && matches!(expr.kind, ExprKind::Name(_) | ExprKind::Index { .. })
            && self.is_signal_data(arena, id)
        {
            return self.signal_read(arena, id);
        }
        self.st.signal_as_data = false;
        match expr.kind {
            ExprKind::Num => {
                let value = num_value(expr.span.text(self.text)).unwrap_or(0.0);
                let constant = if self.expects_dnum(expect) { Value::Dnum(value) } else { Value::Num(value as f32) };
                let idx = self.st.code.constant(constant);
                self.st.code.emit(Instr::Const(idx));
            }
            ExprKind::Str => {
                let idx = self.st.code.constant(Value::Str(string_value(expr.span.text(self.text)).into()));
                self.st.code.emit(Instr::Const(idx));
            }
            ExprKind::Bool(b) => {
                let idx = self.st.code.constant(Value::Bool(b));
                self.st.code.emit(Instr::Const(idx));
            }
            ExprKind::Name(_) => match self.name(id) {
                Some(Resolved::Local(local)) => {
                    self.st.code.emit(Instr::LoadLocal(local.slot));
                }
                Some(Resolved::Global(idx)) => {
                    self.st.code.emit(Instr::LoadGlobal(idx));
                }
                _ => return Err(self.error(expr.span, "not data")),
            },
            ExprKind::Index { base, indices } if self.elem_root(arena, base).is_some() => {
                let (global, slot) = self.elem_root(arena, base).unwrap_or((false, 0));
                let indices = arena.list(indices);
                for &index in indices {
                    self.expr(arena, index, None)?;
                }
                self.st.code.emit(Instr::LoadElem { global, slot, n: indices.len() as u8 });
            }
            ExprKind::Index { .. } | ExprKind::Field { .. } => {
                self.place(arena, id)?;
                self.st.code.emit(Instr::LoadPlace);
            }
            ExprKind::Call { args, .. } => self.call(arena, args, expr.span, super::call::CallOf::Expr(id))?,
            ExprKind::Unary { op, operand } => {
                let start = self.mark();
                self.expr(arena, operand, expect)?;
                if !self.fold_sign(op, start) {
                    self.st.code.emit(Instr::Unary(op));
                }
            }
            ExprKind::Binary { op, lhs, rhs } => {
                // Aggregates compared with typed data take that data's type (§1.3.3).
                let lhs_ty = self.static_type(arena, lhs);
                let rhs_ty = self.static_type(arena, rhs);
                let num_ctx = if self.expects_dnum(expect) { expect } else { None };
                let rhs_leaf = self.leaf_operand(arena, rhs, lhs_ty.or(num_ctx));
                // A leaf on the left is read when the operator runs, so only when the
                // right side cannot change it (it is a leaf too).
                let lhs_leaf = rhs_leaf.and_then(|_| self.leaf_operand(arena, lhs, rhs_ty.or(num_ctx)));
                if lhs_leaf.is_none() {
                    self.expr(arena, lhs, rhs_ty.or(num_ctx))?;
                }
                if rhs_leaf.is_none() {
                    self.expr(arena, rhs, lhs_ty.or(num_ctx))?;
                }
                let (lhs, rhs) = (lhs_leaf.unwrap_or(Operand::Stack), rhs_leaf.unwrap_or(Operand::Stack));
                self.st.code.emit(Instr::BinOp { op, lhs, rhs });
            }
            ExprKind::Paren(inner) => self.expr(arena, inner, expect)?,
            ExprKind::Aggregate(items) => self.aggregate(arena, items, expr.span, expect)?,
            ExprKind::Placeholder(_) | ExprKind::Error => {
                self.st.code.emit(Instr::Placeholder);
            }
        }
        Ok(())
    }

    /// Whether `id` names data of a signal type (signaldi, signaldo, …).
    fn is_signal_data(&self, arena: &Arena, id: ExprId) -> bool {
        self.static_type(arena, id)
            .is_some_and(|(ty, _)| self.prog.types.class(ty) == rapid_sema::types::ValueClass::SemiValue)
    }

    /// Reading a signal: the signal data, then its value (ERR_NO_ALIASIO_DEF when no
    /// AliasIO connected it, manual §1.9; the configuration's own signals are connected
    /// when the I/O system is installed).
    fn signal_read(&mut self, arena: &Arena, id: ExprId) -> Result<(), CompileError> {
        let span = arena.expr(id).span;
        self.st.signal_as_data = true;
        self.expr(arena, id, None)?;
        let name = span.text(self.text).to_string();
        let idx = self.st.code.constant(Value::Str(name.as_str().into()));
        self.st.code.emit(Instr::ReadSignal(idx));
        Ok(())
    }

    /// A local or a literal that `BinOp` can read in place.
    fn leaf_operand(&mut self, arena: &Arena, id: ExprId, expect: Expected) -> Option<Operand> {
        let expr = *arena.expr(id);
        match expr.kind {
            ExprKind::Name(_) => match self.name(id)? {
                Resolved::Local(local) => Some(Operand::Local(local.slot)),
                _ => None,
            },
            ExprKind::Num => {
                let value = num_value(expr.span.text(self.text))?;
                let constant = if self.expects_dnum(expect) { Value::Dnum(value) } else { Value::Num(value as f32) };
                Some(Operand::Const(self.st.code.constant(constant)))
            }
            _ => None,
        }
    }

    fn expects_dnum(&self, expect: Expected) -> bool {
        expect.is_some_and(|(ty, _)| self.prog.types.atomic(ty) == Some(Atomic::Dnum))
    }

    fn aggregate(
        &mut self,
        arena: &Arena,
        items: rapid_syntax::ast::ListRange,
        span: rapid_syntax::Span,
        expect: Expected,
    ) -> Result<(), CompileError> {
        let Some((ty, dims)) = expect else { return Err(self.error(span, "an aggregate without a type")) };
        let items = arena.list(items);
        let start = self.mark();
        if dims[0] > 0 {
            let inner = [dims[1], dims[2], 0];
            for &item in items {
                self.expr(arena, item, Some((ty, inner)))?;
            }
            self.make(start, items.len(), Whole::Array);
            return Ok(());
        }
        let record = self.prog.types.value_of(ty);
        let field_types: Vec<TypeId> = match &self.prog.types.info(record).kind {
            TypeKind::Record(fields) => fields.iter().map(|f| f.ty).collect(),
            _ => {
                // An array parameter of unknown size, or `anytype`: build an array.
                for &item in items {
                    self.expr(arena, item, Some((ty, [0; 3])))?;
                }
                self.make(start, items.len(), Whole::Array);
                return Ok(());
            }
        };
        for (&item, &field_ty) in items.iter().zip(&field_types) {
            self.expr(arena, item, Some((field_ty, [0; 3])))?;
        }
        self.make(start, items.len(), Whole::Record(record));
        Ok(())
    }

    /// Where the code, the constants and the packed aggregates end now.
    fn mark(&self) -> Mark {
        Mark {
            instrs: self.st.code.instrs.len(),
            consts: self.st.code.consts.len(),
            packed: self.st.code.aggregates.len(),
        }
    }

    /// Ends an aggregate whose `n` parts were compiled since `start`: one packed
    /// constant when every part is a literal or a constant aggregate, else the
    /// instruction that builds it at run time.
    fn make(&mut self, start: Mark, n: usize, whole: Whole) {
        if let Some(k) = self.fold(start, n, whole) {
            self.st.code.emit(Instr::Aggregate(k));
            return;
        }
        match whole {
            Whole::Array => self.st.code.emit(Instr::MakeArray(n as u32)),
            Whole::Record(ty) => self.st.code.emit(Instr::MakeRecord(ty, n as u16)),
        };
    }

    /// Packs the aggregate whose `n` parts were compiled since `start` when each part
    /// is one instruction pushing a constant made for it alone (a literal, or an
    /// aggregate packed already): those constants are taken back, in order, into the
    /// new one, which is the value `MakeRecord` or `MakeArray` would build from them.
    fn fold(&mut self, start: Mark, n: usize, whole: Whole) -> Option<u32> {
        let emitted = &self.st.code.instrs[start.instrs..];
        if emitted.len() != n {
            return None;
        }
        let (mut next_const, mut next_packed) = (start.consts, start.packed);
        let mut builder = Builder::with_parts(n);
        for instr in emitted {
            let packable = match *instr {
                Instr::Const(k) if k as usize == next_const => {
                    next_const += 1;
                    builder.leaf(&mut self.st.code.aggregates, &self.st.code.consts[k as usize])
                }
                Instr::Aggregate(k) if k as usize == next_packed => {
                    next_packed += 1;
                    builder.entry(&self.st.code.aggregates, k)
                }
                _ => false,
            };
            if !packable {
                return None;
            }
        }
        if next_const != self.st.code.consts.len() || next_packed != self.st.code.aggregates.len() {
            return None;
        }
        let draft = builder.finish(whole)?;
        self.st.code.instrs.truncate(start.instrs);
        self.st.code.consts.truncate(start.consts);
        self.st.code.aggregates.truncate(start.packed as u32);
        Some(self.st.code.aggregates.add(draft, &mut self.st.shapes))
    }

    /// `-literal` and `+literal` are constants: when the operand compiled since
    /// `start` is one constant num or dnum made for it alone, it is negated in place
    /// (as `ops::unary` would negate it at run time) or kept as it is, so that
    /// aggregates of signed numbers pack too. Whether it folded.
    fn fold_sign(&mut self, op: UnaryOp, start: Mark) -> bool {
        let single = self.st.code.instrs.len() == start.instrs + 1
            && self.st.code.consts.len() == start.consts + 1
            && matches!(self.st.code.instrs[start.instrs], Instr::Const(k) if k as usize == start.consts);
        if !single {
            return false;
        }
        let value = &mut self.st.code.consts[start.consts];
        match (op, &*value) {
            (UnaryOp::Neg, Value::Num(n)) => *value = Value::Num(-n),
            (UnaryOp::Neg, Value::Dnum(d)) => *value = Value::Dnum(-d),
            (UnaryOp::Plus, Value::Num(_) | Value::Dnum(_)) => {}
            _ => return false,
        }
        true
    }

    /// An array named directly (`a` in `a{i}`): (global?, slot).
    pub(crate) fn elem_root(&self, arena: &Arena, base: ExprId) -> Option<(bool, u32)> {
        match arena.expr(base).kind {
            ExprKind::Name(_) => match self.name(base)? {
                Resolved::Local(local) => Some((false, local.slot)),
                Resolved::Global(idx) => Some((true, idx)),
                _ => None,
            },
            _ => None,
        }
    }

    /// Emits code that pushes the place of a data reference (`a`, `a{i}`, `r.c`...).
    pub(crate) fn place(&mut self, arena: &Arena, id: ExprId) -> Result<(), CompileError> {
        let expr = *arena.expr(id);
        match expr.kind {
            ExprKind::Name(_) => match self.name(id) {
                Some(Resolved::Local(local)) => {
                    self.st.code.emit(Instr::PlaceLocal(local.slot));
                }
                Some(Resolved::Global(idx)) => {
                    self.st.code.emit(Instr::PlaceGlobal(idx));
                }
                _ => return Err(self.error(expr.span, "not data")),
            },
            ExprKind::Index { base, indices } => {
                self.place(arena, base)?;
                let indices = arena.list(indices);
                for &index in indices {
                    self.expr(arena, index, None)?;
                }
                self.st.code.emit(Instr::PlaceIndex(indices.len() as u8));
            }
            ExprKind::Field { base, field } => {
                self.place(arena, base)?;
                let (ty, _) = self.static_type(arena, base).ok_or_else(|| self.error(expr.span, "unknown record"))?;
                let record = self.prog.types.value_of(ty);
                let idx = match &self.prog.types.info(record).kind {
                    TypeKind::Record(fields) => fields.iter().position(|f| f.name == field),
                    _ => None,
                };
                let idx = idx.ok_or_else(|| self.error(expr.span, "unknown record component"))?;
                self.st.code.emit(Instr::PlaceField(idx as u16));
            }
            ExprKind::Paren(inner) => self.place(arena, inner)?,
            ExprKind::Placeholder(_) => {
                self.st.code.emit(Instr::Placeholder);
            }
            _ => return Err(self.error(expr.span, "this expression is not data that can be referred to")),
        }
        Ok(())
    }

    /// The type of an expression (and, for data, its known dimension sizes): the
    /// declared type of a data reference or a function's return type, else the type
    /// the checker gave it. A numeric literal and arithmetic of literals only have
    /// none: they take the context's (`ExprType::Numeric`).
    pub(crate) fn static_type(&self, arena: &Arena, id: ExprId) -> Expected {
        let expr = arena.expr(id);
        let typed = match expr.kind {
            ExprKind::Name(_) | ExprKind::Index { .. } | ExprKind::Field { .. } | ExprKind::Call { .. } => None,
            ExprKind::Paren(_) => None,
            _ => self.facts.and_then(|facts| facts.ty(id)),
        };
        match typed {
            Some(ExprType::Numeric) => return None,
            Some(ExprType::Of { ty, rank }) => return Some((ty, expected_dims(rank, [0; 3]))),
            None => {}
        }
        // Data references and calls: through what the checker resolved.
        match expr.kind {
            ExprKind::Name(_) => match self.name(id)? {
                Resolved::Local(local) => Some((local.ty, expected_dims(local.rank, local.dims))),
                Resolved::Global(idx) => {
                    let data = self.prog.data(idx)?;
                    Some((data.ty, expected_dims(data.rank, data.dims)))
                }
                _ => None,
            },
            ExprKind::Index { base, .. } => self.static_type(arena, base).map(|(ty, _)| (ty, [0; 3])),
            ExprKind::Field { base, field } => {
                let (ty, _) = self.static_type(arena, base)?;
                match &self.prog.types.info(self.prog.types.value_of(ty)).kind {
                    TypeKind::Record(fields) => fields.iter().find(|f| f.name == field).map(|f| (f.ty, [0; 3])),
                    _ => None,
                }
            }
            ExprKind::Paren(inner) => self.static_type(arena, inner),
            ExprKind::Call { .. } => match self.callee(super::call::CallOf::Expr(id))? {
                Resolved::Routine(idx) => self.prog.routines[idx as usize].ret.map(|t| (t, [0; 3])),
                _ => None,
            },
            _ => None,
        }
    }
}

/// Dimension sizes for an expected type: 0 past the rank (scalar levels), and
/// `u32::MAX` for a dimension whose size is not known (array parameters), so an
/// aggregate still knows it builds an array.
pub(crate) fn expected_dims(rank: u8, dims: [u32; 3]) -> [u32; 3] {
    let mut out = [0u32; 3];
    for (idx, slot) in out.iter_mut().enumerate().take((rank as usize).min(3)) {
        *slot = if dims[idx] == 0 { u32::MAX } else { dims[idx] };
    }
    out
}
