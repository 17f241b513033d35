//! Checks on declarations (§1.2.2, §1.1.5): array dimensions, initial values
//! (constant and literal expressions), storage rules for value, semi-value and
//! non-value types, FUNC return types and parameter lists.

use rapid_syntax::ast::{Arena, DataDecl, DeclScope, ExprKind, Routine, RoutineKind, Storage};
use rustc_hash::FxHashMap;

use crate::checker::Checker;
use crate::codes::Code;
use crate::expr::{Expect, What};
use crate::types::{self, ValueClass};

impl Checker<'_> {
    /// Checks one data declaration, module-level or routine data, whose entry in the
    /// data table is `data`.
    pub(crate) fn check_data_decl(&mut self, decl: &DataDecl, arena: &Arena, data: u32, in_routine: bool) {
        if in_routine {
            if decl.storage == Storage::Pers {
                self.diag(
                    Code::PersInRoutine,
                    decl.span,
                    "a PERS may be declared only at module level, not inside a routine".into(),
                );
            }
            if let (DeclScope::Local | DeclScope::Task, Some(span)) = (decl.scope, decl.scope_span) {
                let word = self.text(span).to_ascii_uppercase();
                self.diag(Code::LocalInRoutine, span, format!("{word} may be used only on module-level declarations"));
            }
        }
        let dims = self.check_dims(decl, arena);
        self.datas[data as usize].dims = dims;
        let ty = self.datas[data as usize].ty;
        let class = self.types.class(ty);
        let name = self.text(decl.name.span);
        let type_name = self.type_name(ty);
        if class != ValueClass::Value && decl.storage != Storage::Var {
            let word = if decl.storage == Storage::Pers { "PERS" } else { "CONST" };
            self.diag(
                Code::NonValueDeclaration,
                decl.span,
                format!("`{type_name}` is a {} type: it cannot be declared {word}", class_word(class)),
            );
            return;
        }
        match decl.init {
            Some(init) if class == ValueClass::NonValue => {
                let span = arena.expr(init).span;
                self.diag(
                    Code::NonValueDeclaration,
                    span,
                    format!("`{name}` has the non-value type `{type_name}` and cannot be given an initial value"),
                );
            }
            Some(init) if class == ValueClass::SemiValue => {
                let span = arena.expr(init).span;
                self.diag(
                    Code::SemiValueWrite,
                    span,
                    format!(
                        "signal `{name}` cannot be initialised; signals are bound by the I/O configuration or AliasIO"
                    ),
                );
            }
            Some(init) => self.check_init(decl, arena, init, ty, &dims),
            None => self.check_missing_init(decl),
        }
    }

    fn check_init(
        &mut self,
        decl: &DataDecl,
        arena: &Arena,
        init: rapid_syntax::ast::ExprId,
        ty: types::TypeId,
        dims: &[u32; 3],
    ) {
        let span = arena.expr(init).span;
        if decl.storage == Storage::Pers && !self.is_literal(arena, init) {
            self.diag(
                Code::PersInitNotLiteral,
                span,
                "the initial value of a PERS must be a literal expression (literals and aggregates of literals)".into(),
            );
        } else if decl.storage != Storage::Pers && !self.is_constant(arena, init) {
            let what = if decl.storage == Storage::Const { "a CONST" } else { "a VAR" };
            self.diag(Code::ConstInitNotConstant, span, format!("the initial value of {what} must be a constant expression: no variables, persistents or function calls"));
        }
        let rank = decl.dims.len().min(3);
        let expect = Expect { ty, dims: &dims[..rank] };
        self.expect_value(arena, init, expect, What::Text("the initial value"));
    }

    fn check_missing_init(&mut self, decl: &DataDecl) {
        match (decl.storage, decl.scope) {
            (Storage::Const, _) => {
                let name = self.text(decl.name.span);
                self.diag(Code::ConstInitMissing, decl.span, format!("CONST `{name}` needs a value"));
            }
            (Storage::Pers, DeclScope::Local | DeclScope::Task) => {
                let name = self.text(decl.name.span);
                self.diag(
                    Code::PersInitMissing,
                    decl.span,
                    format!("LOCAL and TASK persistents need an initial value; `{name}` has none"),
                );
            }
            _ => {}
        }
    }

    /// Dimensions must be positive integer constant expressions, and the array must fit
    /// the one limit the interpreter applies too (`rapid_limits::ARRAY_ELEMENTS`), so
    /// every array `rapid check` accepts, `rapid run` can hold.
    fn check_dims(&mut self, decl: &DataDecl, arena: &Arena) -> [u32; 3] {
        let mut dims = [0u32; 3];
        let mut sizes = Vec::with_capacity(decl.dims.len());
        for (slot, &dim) in dims.iter_mut().zip(&decl.dims) {
            let expr = arena.expr(dim);
            if matches!(expr.kind, ExprKind::Placeholder(_) | ExprKind::Error) {
                continue;
            }
            self.expect_value(arena, dim, Expect::scalar(self.core.num), What::Text("an array dimension"));
            match self.const_num(arena, dim) {
                Some(v) if v >= 1.0 && v.fract() == 0.0 && v.is_finite() => {
                    sizes.push(v);
                    *slot = v.min(f64::from(u32::MAX)) as u32;
                }
                Some(v) => {
                    self.diag(
                        Code::BadArrayDimension,
                        expr.span,
                        format!("array dimension {v} is not a positive integer"),
                    );
                }
                None => {
                    self.diag(
                        Code::BadArrayDimension,
                        expr.span,
                        "an array dimension must be a constant expression with a positive integer value".into(),
                    );
                }
            }
        }
        let elements = rapid_limits::array_elements(&sizes);
        if elements > rapid_limits::ARRAY_ELEMENTS as f64 {
            let name = self.text(decl.name.span);
            self.diag(Code::ArrayTooLarge, decl.span, rapid_limits::array_too_large(name, elements));
            // Unknown sizes from here on: nothing downstream sizes anything by them.
            dims = [0; 3];
        }
        dims
    }

    /// Checks a routine's header: return type and parameter list (§1.1.5).
    pub(crate) fn check_routine_header(&mut self, routine: &Routine) {
        if let (RoutineKind::Func, Some(ret)) = (routine.kind, routine.ret_ty) {
            if let Some(crate::symbols::Def::Type(ty)) = self.lookup(ret.sym) {
                let class = self.types.class(ty);
                if class != ValueClass::Value {
                    let name = self.type_name(ty);
                    self.diag(
                        Code::FuncReturnsNonValue,
                        ret.span,
                        format!("a FUNC must return a value type; `{name}` is a {} type", class_word(class)),
                    );
                }
            }
        }
        let mut group_sizes: FxHashMap<u16, usize> = FxHashMap::default();
        for param in &routine.params {
            *group_sizes.entry(param.group).or_default() += 1;
        }
        for param in routine.params.iter().filter(|p| p.placeholder.is_none()) {
            let name = self.text(param.name.span);
            if param.ty.sym == self.known.switch && (!param.optional || param.rank > 0) {
                let why = if param.rank > 0 { "cannot be an array" } else { "must be optional: write `\\switch`" };
                self.diag(Code::SwitchNotOptional, param.span, format!("switch parameter `{name}` {why}"));
            }
            if !param.optional && group_sizes.get(&param.group).copied().unwrap_or(0) > 1 {
                self.diag(Code::RequiredAlternatives, param.span, format!("parameter `{name}` is in a `|` group but is not optional; only optional parameters may exclude each other"));
            }
        }
    }
}

fn class_word(class: ValueClass) -> &'static str {
    match class {
        ValueClass::Value => "value",
        ValueClass::SemiValue => "semi-value",
        ValueClass::NonValue => "non-value",
    }
}
