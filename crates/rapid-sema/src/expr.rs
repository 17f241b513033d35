//! Typing expressions (§1.3): data references, literals, aggregates typed from their
//! context (§1.3.3), function calls and the operator table of §1.3.1.

use rapid_syntax::ast::{Arena, BinaryOp, ExprId, ExprKind, UnaryOp};
use rapid_syntax::literal::num_value;
use rapid_syntax::Span;

use crate::checker::Checker;
use crate::codes::Code;
use crate::facts::ExprType;
use crate::symbols::{Def, ANY_RANK};
use crate::types::{self, Atomic, TypeId, ValueClass};

/// The type of an expression: a data type and an array rank (0 for scalars).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Ty {
    pub(crate) ty: TypeId,
    pub(crate) rank: u8,
}

impl Ty {
    pub(crate) const ERROR: Ty = Ty { ty: types::ERROR, rank: 0 };

    pub(crate) fn scalar(ty: TypeId) -> Ty {
        Ty { ty, rank: 0 }
    }
}

/// What the context expects: a type and the known sizes of its dimensions (0 where
/// unknown). Aggregates take their type from it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Expect<'d> {
    pub(crate) ty: TypeId,
    pub(crate) dims: &'d [u32],
}

impl<'d> Expect<'d> {
    pub(crate) fn scalar(ty: TypeId) -> Expect<'static> {
        Expect { ty, dims: &[] }
    }

    fn rank(&self) -> u8 {
        self.dims.len() as u8
    }
}

/// What a checked value is, for the message when its type is wrong (formatted only
/// then, so the common case allocates nothing).
#[derive(Debug, Clone, Copy)]
pub(crate) enum What<'a> {
    Text(&'a str),
    /// Component `idx` of record type `record`.
    Component(TypeId, usize),
}

/// The largest magnitude a num (IEEE single) can hold.
const NUM_MAX: f64 = f32::MAX as f64;

impl Checker<'_> {
    /// Types `id`, reporting what is wrong inside it. `expect` types aggregates.
    /// The type goes into the item's facts for the compiler.
    pub(crate) fn expr(&mut self, arena: &Arena, id: ExprId, expect: Option<Expect<'_>>) -> Ty {
        let ty = self.type_expr(arena, id, expect);
        if self.facts.recording {
            let fact = self.type_fact(arena, id, ty);
            self.facts.set_type(id, fact);
        }
        ty
    }

    /// The fact recorded for `id` typed `ty`: a literal and arithmetic of literals
    /// only are numeric, typed by their context (see [`ExprType::Numeric`]); an
    /// operand was typed (and recorded) before its operator.
    fn type_fact(&self, arena: &Arena, id: ExprId, ty: Ty) -> Option<ExprType> {
        if ty.ty == types::ERROR {
            return None;
        }
        let numeric = |id: ExprId| self.facts.ty(id) == Some(ExprType::Numeric);
        let literal = match arena.expr(id).kind {
            ExprKind::Num => true,
            ExprKind::Paren(inner) | ExprKind::Unary { op: UnaryOp::Neg | UnaryOp::Plus, operand: inner } => {
                numeric(inner)
            }
            ExprKind::Binary {
                op: BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div | BinaryOp::IntDiv | BinaryOp::Mod,
                lhs,
                rhs,
            } => numeric(lhs) && numeric(rhs),
            _ => false,
        };
        Some(if literal { ExprType::Numeric } else { ExprType::Of { ty: ty.ty, rank: ty.rank } })
    }

    fn type_expr(&mut self, arena: &Arena, id: ExprId, expect: Option<Expect<'_>>) -> Ty {
        let expr = *arena.expr(id);
        match expr.kind {
            ExprKind::Num => self.num_literal(expr.span, expect),
            ExprKind::Str => Ty::scalar(self.core.string),
            ExprKind::Bool(_) => Ty::scalar(self.core.bool_),
            ExprKind::Placeholder(_) | ExprKind::Error => Ty::ERROR,
            ExprKind::Name(sym) => self.name_expr(id, sym, expr.span, expect),
            ExprKind::Index { base, indices } => self.index_expr(arena, base, indices, expr.span),
            ExprKind::Field { base, field } => self.field_expr(arena, base, field, expr.span),
            ExprKind::Call { name, args } => self.call_expr(arena, id, name, args, expr.span),
            ExprKind::Unary { op, operand } => self.unary_expr(arena, op, operand, expr.span, expect),
            ExprKind::Binary { op, lhs, rhs } => self.binary_expr(arena, op, lhs, rhs, expr.span),
            ExprKind::Paren(inner) => self.expr(arena, inner, expect),
            ExprKind::Aggregate(items) => match expect {
                Some(expect) => self.aggregate(arena, items, expr.span, expect),
                None => {
                    self.diag(
                        Code::AggregateWithoutType,
                        expr.span,
                        "the type of this aggregate cannot be told from its context".into(),
                    );
                    for &item in arena.list(items) {
                        self.expr(arena, item, None);
                    }
                    Ty::ERROR
                }
            },
        }
    }

    /// Types `id` and requires a value assignable to `want` (E0301 otherwise).
    pub(crate) fn expect_value(&mut self, arena: &Arena, id: ExprId, want: Expect<'_>, what: What<'_>) -> Ty {
        let got = self.expr(arena, id, Some(want));
        self.require_compatible(want.ty, want.rank(), got, arena.expr(id).span, what);
        got
    }

    pub(crate) fn require_compatible(&mut self, want: TypeId, want_rank: u8, got: Ty, span: Span, what: What<'_>) {
        if got.ty == types::ERROR || want == types::ERROR {
            return;
        }
        let rank_ok = want_rank == got.rank || (want_rank == ANY_RANK && got.rank > 0);
        if rank_ok && self.types.compatible(want, got.ty) {
            return;
        }
        let (w, g) = (self.describe(want, want_rank), self.describe(got.ty, got.rank));
        let what = match what {
            What::Text(text) => text.to_string(),
            What::Component(record, idx) => {
                let field =
                    self.types.record_fields(record).and_then(|f| f.get(idx)).map_or("?", |f| f.display.as_str());
                format!("component `{field}`")
            }
        };
        self.diag(Code::TypeMismatch, span, format!("{what} must be {w}, found {g}"));
    }

    /// `num`, `array of num`, `2-dimensional array of pos`.
    pub(crate) fn describe(&self, ty: TypeId, rank: u8) -> String {
        let name = self.types.name(ty);
        match rank {
            0 => format!("`{name}`"),
            1 => format!("an array of `{name}`"),
            ANY_RANK => format!("an array of `{name}`"),
            n => format!("a {n}-dimensional array of `{name}`"),
        }
    }

    fn num_literal(&mut self, span: Span, expect: Option<Expect<'_>>) -> Ty {
        let wants_dnum = expect.is_some_and(|e| self.types.atomic(e.ty) == Some(Atomic::Dnum));
        let text = self.text(span);
        // Only literals near ±3.4E38 are converted for the range check.
        let may_exceed = rapid_syntax::literal::decimal_magnitude_bound(text) >= 38;
        // A literal beyond even f64 (`1e400`) already has the lexer's one error.
        let value = num_value(text).filter(|v| v.is_finite()).unwrap_or(0.0);
        if may_exceed && !wants_dnum && value.abs() > NUM_MAX {
            let text = self.text(span);
            self.diag(
                Code::NumLiteralRange,
                span,
                format!("`{text}` is outside the range of num (about ±3.4E38); use a dnum"),
            );
        }
        Ty::scalar(if wants_dnum { self.core.dnum } else { self.core.num })
    }

    fn name_expr(&mut self, id: ExprId, sym: rapid_syntax::Symbol, span: Span, expect: Option<Expect<'_>>) -> Ty {
        let def = self.lookup(sym);
        self.note_name(id, def);
        match def {
            Some(Def::Data(data)) => {
                let info = self.data(data);
                Ty { ty: info.ty, rank: info.rank }
            }
            Some(def @ (Def::Routine(_) | Def::Type(_))) => {
                let text = self.text(span);
                let what = if matches!(def, Def::Routine(_)) { "a routine" } else { "a data type" };
                self.diag(Code::NotData, span, format!("`{text}` is {what}, not data"));
                Ty::ERROR
            }
            None if sym == self.known.placeholder_id => Ty::ERROR,
            None if self.virtual_signals && self.virtual_pending.contains(&sym) => {
                let k = self.virtual_pending.iter().position(|s| *s == sym).unwrap_or(0);
                self.note_virtual(id, k);
                Ty::scalar(self.virtual_datas.get(k).map_or(types::ERROR, |d| d.ty))
            }
            None if self.virtual_signals && expect.is_some_and(|e| e.dims.is_empty() && self.is_signal_type(e.ty)) => {
                let ty = expect.map_or(types::ERROR, |e| e.ty);
                self.declare_virtual_signal(sym, span, ty);
                self.note_virtual(id, self.virtual_pending.len() - 1);
                Ty::scalar(ty)
            }
            None => {
                let message = format!("undefined data `{}`", self.text(span));
                self.undefined(Code::UndefinedData, span, sym, message);
                Ty::ERROR
            }
        }
    }

    fn index_expr(&mut self, arena: &Arena, base: ExprId, indices: rapid_syntax::ast::ListRange, span: Span) -> Ty {
        let base_ty = self.expr(arena, base, None);
        let n_indices = indices.len as u8;
        for &index in arena.list(indices) {
            self.expect_value(arena, index, Expect::scalar(self.core.num), What::Text("an array index"));
        }
        if base_ty.ty == types::ERROR {
            return Ty::ERROR;
        }
        if base_ty.rank == 0 {
            let text = self.text(arena.expr(base).span);
            self.diag(Code::BadIndex, span, format!("`{text}` is not an array"));
            return Ty::ERROR;
        }
        if base_ty.rank != n_indices && base_ty.rank != ANY_RANK {
            let text = self.text(arena.expr(base).span);
            self.diag(
                Code::BadIndex,
                span,
                format!("`{text}` has {} dimensions but is indexed with {n_indices}", base_ty.rank),
            );
            return Ty::ERROR;
        }
        Ty::scalar(base_ty.ty)
    }

    fn field_expr(&mut self, arena: &Arena, base: ExprId, field: rapid_syntax::Symbol, span: Span) -> Ty {
        let base_ty = self.expr(arena, base, None);
        let field_text = self.text(span).rsplit('.').next().unwrap_or("").trim();
        if let Some(option) = self.unknowns.opaque.get(&base_ty.ty) {
            let ty = self.type_name(base_ty.ty);
            let message = format!(
                "the components of `{ty}` (option {}) are not public, so `{field_text}` cannot be checked or used here",
                option.name
            );
            self.diag(Code::UnknownComponent, span, message);
            return Ty::ERROR;
        }
        if base_ty.ty == types::ERROR || self.types.is_lenient(base_ty.ty) {
            return Ty::ERROR;
        }
        if base_ty.rank > 0 {
            self.diag(
                Code::UnknownComponent,
                span,
                format!("an array has no component `{field_text}`; index it first"),
            );
            return Ty::ERROR;
        }
        let found =
            self.types.record_fields(base_ty.ty).map(|fields| fields.iter().find(|f| f.name == field).map(|f| f.ty));
        match found {
            Some(Some(ty)) => Ty::scalar(ty),
            Some(None) => {
                let ty = self.type_name(base_ty.ty);
                self.diag(Code::UnknownComponent, span, format!("record type `{ty}` has no component `{field_text}`"));
                Ty::ERROR
            }
            None => {
                let ty = self.type_name(base_ty.ty);
                self.diag(
                    Code::UnknownComponent,
                    span,
                    format!("`{ty}` is not a record type, so it has no component `{field_text}`"),
                );
                Ty::ERROR
            }
        }
    }

    fn unary_expr(
        &mut self,
        arena: &Arena,
        op: UnaryOp,
        operand: ExprId,
        span: Span,
        expect: Option<Expect<'_>>,
    ) -> Ty {
        let inner_expect = match op {
            UnaryOp::Not => None,
            _ => expect.filter(|e| e.dims.is_empty()),
        };
        let ty = self.expr(arena, operand, inner_expect);
        if ty.ty == types::ERROR {
            return Ty::ERROR;
        }
        let value = self.types.value_of(ty.ty);
        let ok = ty.rank == 0
            && match op {
                UnaryOp::Not => value == self.core.bool_,
                UnaryOp::Neg | UnaryOp::Plus => self.types.is_numeric(value) || value == self.core.pos,
            };
        if !ok {
            let word = match op {
                UnaryOp::Not => "NOT",
                UnaryOp::Neg => "-",
                UnaryOp::Plus => "+",
            };
            let got = self.describe(ty.ty, ty.rank);
            self.diag(Code::OperatorTypes, span, format!("operator {word} is not defined for {got}"));
            return Ty::ERROR;
        }
        Ty::scalar(value)
    }

    fn binary_expr(&mut self, arena: &Arena, op: BinaryOp, lhs: ExprId, rhs: ExprId, span: Span) -> Ty {
        let (l, r) = self.operand_types(arena, op, lhs, rhs);
        if l.ty == types::ERROR || r.ty == types::ERROR {
            return match op {
                BinaryOp::Lt
                | BinaryOp::Le
                | BinaryOp::Eq
                | BinaryOp::Gt
                | BinaryOp::Ge
                | BinaryOp::Ne
                | BinaryOp::And
                | BinaryOp::Or
                | BinaryOp::Xor => Ty::scalar(self.core.bool_),
                _ => Ty::ERROR,
            };
        }
        match self.operator_result(op, l, r) {
            Some(ty) => Ty::scalar(ty),
            None => {
                if matches!(op, BinaryOp::Eq | BinaryOp::Ne) && self.types.class(l.ty) == ValueClass::NonValue {
                    let got = self.type_name(l.ty);
                    self.diag(
                        Code::NonValueUse,
                        span,
                        format!("`{got}` is a non-value type: its data cannot be compared"),
                    );
                    return Ty::scalar(self.core.bool_);
                }
                let (a, b) = (self.describe(l.ty, l.rank), self.describe(r.ty, r.rank));
                let word = op.text();
                self.diag(Code::OperatorTypes, span, format!("operator {word} is not defined for {a} and {b}"));
                Ty::ERROR
            }
        }
    }

    /// Types both operands. An aggregate beside typed data takes that data's type
    /// (§1.3.3: the type comes from the context, and the other operand is the
    /// context): `p1 + [10,10,30]` is a pos, `o * [0,0,0,1]` an orient. An aggregate
    /// beside an aggregate has no context and stays E0303, as the manual's
    /// `[1,-100,12] = [a,b,b]` example says. Beside an atomic operand of an arithmetic
    /// operator (`2 * [1,2,3]`) no aggregate type is possible, so that stays E0303 too.
    fn operand_types(&mut self, arena: &Arena, op: BinaryOp, lhs: ExprId, rhs: ExprId) -> (Ty, Ty) {
        let (lhs_agg, rhs_agg) = (is_aggregate(arena, lhs), is_aggregate(arena, rhs));
        if lhs_agg != rhs_agg {
            let (typed, agg) = if lhs_agg { (rhs, lhs) } else { (lhs, rhs) };
            let typed_ty = self.expr(arena, typed, None);
            let comparison = matches!(op, BinaryOp::Eq | BinaryOp::Ne);
            let agg_ty = if typed_ty.ty == types::ERROR {
                Ty::ERROR
            } else if !comparison && typed_ty.rank == 0 && !self.is_record(typed_ty.ty) {
                self.expr(arena, agg, None)
            } else {
                let dims = vec![0u32; typed_ty.rank as usize];
                self.expr(arena, agg, Some(Expect { ty: typed_ty.ty, dims: &dims }))
            };
            return if lhs_agg { (agg_ty, typed_ty) } else { (typed_ty, agg_ty) };
        }
        let l = self.expr(arena, lhs, None);
        let r = self.expr(arena, rhs, None);
        (l, r)
    }

    /// Whether `ty` is one of the signal types (signaldi … signalgo).
    fn is_signal_type(&self, ty: TypeId) -> bool {
        let name = self.types.name(ty);
        ["signaldi", "signaldo", "signalai", "signalao", "signalgi", "signalgo"]
            .iter()
            .any(|n| name.eq_ignore_ascii_case(n))
    }

    /// Takes `sym` as signal data of the configuration (`--virtual-io`): the name is a
    /// signal of the cell's I/O configuration, which is not at hand. Declared when the
    /// routine ends; until then its uses find it here.
    fn declare_virtual_signal(&mut self, sym: rapid_syntax::Symbol, span: Span, ty: TypeId) {
        if self.virtual_pending.contains(&sym) {
            return;
        }
        self.virtual_pending.push(sym);
        self.virtual_datas.push(crate::symbols::DataInfo {
            display: self.text(span).to_string(),
            ty,
            rank: 0,
            dims: [0; 3],
            kind: crate::symbols::DataKind::Var,
            const_value: None,
            optional: false,
            origin: crate::symbols::DeclOrigin::CONFIGURED,
            system_global: false,
        });
    }

    /// Records that name `id` is pending virtual signal `k`, by the number it will have.
    fn note_virtual(&mut self, id: ExprId, k: usize) {
        if self.facts.recording {
            let denotes = self.virtual_data(k);
            self.facts.set_name(id, denotes);
        }
    }

    /// Declares the names [`Checker::declare_virtual_signal`] took as global signal data.
    pub(crate) fn declare_virtual_signals(&mut self) {
        let datas = std::mem::take(&mut self.virtual_datas);
        for (sym, data) in std::mem::take(&mut self.virtual_pending).into_iter().zip(datas) {
            let (name, ty) = (data.display.clone(), data.ty);
            self.datas.push(data);
            self.scopes.builtins.insert(sym, Def::Data(self.datas.len() as u32 - 1));
            let type_name = self.types.name(ty).to_string();
            self.virtual_found.push(crate::PredefinedData { name, type_name });
        }
    }

    /// Whether `ty` is a record type (through aliases); lenient types count as records,
    /// since they take any aggregate.
    fn is_record(&self, ty: TypeId) -> bool {
        self.types.is_lenient(ty) || self.types.record_fields(self.types.value_of(ty)).is_some()
    }

    /// The result type of `l op r` per §1.3.1, or `None` when not defined.
    fn operator_result(&self, op: BinaryOp, l: Ty, r: Ty) -> Option<TypeId> {
        let c = self.core;
        let (lv, rv) = (self.types.value_of(l.ty), self.types.value_of(r.ty));
        if matches!(op, BinaryOp::Eq | BinaryOp::Ne) {
            let same_shape = l.rank == r.rank;
            let value =
                self.types.class(l.ty) != ValueClass::NonValue && self.types.class(r.ty) != ValueClass::NonValue;
            let comparable = self.types.compatible(l.ty, r.ty) || self.types.compatible(r.ty, l.ty);
            return (same_shape && value && comparable).then_some(c.bool_);
        }
        if l.rank != 0 || r.rank != 0 {
            return None;
        }
        let numeric = |t: TypeId| self.types.is_numeric(t);
        let num_result = || if lv == c.dnum || rv == c.dnum { c.dnum } else { c.num };
        match op {
            BinaryOp::Add if lv == c.string && rv == c.string => Some(c.string),
            BinaryOp::Add | BinaryOp::Sub if lv == c.pos && rv == c.pos => Some(c.pos),
            BinaryOp::Mul if lv == c.pos && (rv == c.pos || numeric(rv)) => Some(c.pos),
            BinaryOp::Mul if numeric(lv) && rv == c.pos => Some(c.pos),
            BinaryOp::Mul if lv == c.orient && rv == c.orient => Some(c.orient),
            BinaryOp::Div if lv == c.pos && numeric(rv) => Some(c.pos),
            BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div | BinaryOp::IntDiv | BinaryOp::Mod
                if numeric(lv) && numeric(rv) =>
            {
                Some(num_result())
            }
            BinaryOp::Lt | BinaryOp::Le | BinaryOp::Gt | BinaryOp::Ge if numeric(lv) && numeric(rv) => Some(c.bool_),
            BinaryOp::And | BinaryOp::Or | BinaryOp::Xor if lv == c.bool_ && rv == c.bool_ => Some(c.bool_),
            _ => None,
        }
    }

    /// An aggregate checked against the expected record or array shape.
    fn aggregate(&mut self, arena: &Arena, items: rapid_syntax::ast::ListRange, span: Span, expect: Expect<'_>) -> Ty {
        let items = arena.list(items);
        if self.types.is_lenient(expect.ty) {
            // An unresolved or opaque type accepts any shape: nested aggregates too,
            // so one undefined type (or an option type whose components are not
            // public) gives no second diagnostic.
            for &item in items {
                self.expr(arena, item, Some(Expect::scalar(expect.ty)));
            }
            return Ty { ty: expect.ty, rank: expect.rank() };
        }
        if let Some((&size, inner_dims)) = expect.dims.split_first() {
            if size != 0 && size as usize != items.len() {
                self.diag(
                    Code::AggregateShape,
                    span,
                    format!("the array has {size} elements but the aggregate gives {}", items.len()),
                );
            }
            let inner = Expect { ty: expect.ty, dims: inner_dims };
            for &item in items {
                self.expect_value(arena, item, inner, What::Text("an array element"));
            }
            return Ty { ty: expect.ty, rank: expect.rank() };
        }
        let record = self.types.value_of(expect.ty);
        let Some(n_fields) = self.types.record_fields(record).map(<[_]>::len) else {
            let ty = self.type_name(expect.ty);
            self.diag(
                Code::TypeMismatch,
                span,
                format!("an aggregate cannot be a `{ty}`: only records and arrays are written as aggregates"),
            );
            return Ty::ERROR;
        };
        if n_fields != items.len() {
            let ty = self.type_name(expect.ty);
            self.diag(
                Code::AggregateShape,
                span,
                format!("`{ty}` has {n_fields} components but the aggregate gives {}", items.len()),
            );
        }
        for (idx, &item) in items.iter().enumerate() {
            match self.types.record_fields(record).and_then(|f| f.get(idx)).map(|f| f.ty) {
                Some(field_ty) => {
                    self.expect_value(arena, item, Expect::scalar(field_ty), What::Component(record, idx));
                }
                None => {
                    self.expr(arena, item, None);
                }
            }
        }
        Ty::scalar(expect.ty)
    }

    /// Whether `ty` is a record or atomic value type that a condition can test.
    pub(crate) fn is_bool(&self, ty: Ty) -> bool {
        ty.rank == 0 && (self.types.value_of(ty.ty) == self.core.bool_ || self.types.is_lenient(ty.ty))
    }
}

/// Whether `id` is an aggregate, seen through parentheses.
fn is_aggregate(arena: &Arena, id: ExprId) -> bool {
    match arena.expr(id).kind {
        ExprKind::Aggregate(_) => true,
        ExprKind::Paren(inner) => is_aggregate(arena, inner),
        _ => false,
    }
}
