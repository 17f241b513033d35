//! The type table: atomic, record, alias, non-value and semi-value types (§1.2.1),
//! with alias equivalence and the value / semi-value / non-value classes.

use rapid_syntax::{Span, Symbol};

/// Index of a type in the [`Types`] table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TypeId(u32);

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Atomic {
    Num,
    Dnum,
    Bool,
    String,
}

#[derive(Debug, Clone)]
pub struct Field {
    pub name: Symbol,
    pub display: String,
    pub ty: TypeId,
}

#[derive(Debug, Clone)]
pub enum TypeKind {
    /// Stands for a type that could not be resolved; accepts everything, so one
    /// mistake gives one diagnostic.
    Error,
    /// `anytype` in built-in signatures.
    Any,
    /// The `switch` type of optional parameters.
    Switch,
    Atomic(Atomic),
    Record(Vec<Field>),
    Alias(TypeId),
    NonValue,
    /// A signal type and the value type it reads as.
    SemiValue(TypeId),
    /// Declared, components not resolved yet.
    Pending,
}

/// Whether a type's data can take part in value operations (§1.2.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueClass {
    Value,
    SemiValue,
    NonValue,
}

#[derive(Debug, Clone)]
pub struct TypeInfo {
    pub display: String,
    pub kind: TypeKind,
    pub span: Span,
}

/// Every type of the program, built-ins first.
#[derive(Debug, Clone)]
pub struct Types {
    infos: Vec<TypeInfo>,
}

pub const ERROR: TypeId = TypeId(0);
pub const ANY: TypeId = TypeId(1);
pub const SWITCH: TypeId = TypeId(2);

impl Default for Types {
    fn default() -> Types {
        Types::new()
    }
}

impl Types {
    pub fn new() -> Types {
        let special = |display: &str, kind| TypeInfo { display: display.into(), kind, span: Span::default() };
        Types {
            infos: vec![
                special("<error>", TypeKind::Error),
                special("anytype", TypeKind::Any),
                special("switch", TypeKind::Switch),
            ],
        }
    }

    pub fn add(&mut self, info: TypeInfo) -> TypeId {
        self.infos.push(info);
        TypeId(self.infos.len() as u32 - 1)
    }

    pub fn info(&self, ty: TypeId) -> &TypeInfo {
        &self.infos[ty.0 as usize]
    }

    pub fn set_kind(&mut self, ty: TypeId, kind: TypeKind) {
        self.infos[ty.0 as usize].kind = kind;
    }

    pub fn name(&self, ty: TypeId) -> &str {
        &self.info(ty).display
    }

    /// Every type of the table with its name (to match types between two programs,
    /// e.g. the tasks of one controller).
    pub fn named(&self) -> impl Iterator<Item = (TypeId, &str)> + '_ {
        self.infos.iter().enumerate().map(|(i, info)| (TypeId(i as u32), info.display.as_str()))
    }

    /// The type named `name` (any letter case), predefined or declared.
    pub fn find(&self, name: &str) -> Option<TypeId> {
        self.infos.iter().position(|info| info.display.eq_ignore_ascii_case(name)).map(|i| TypeId(i as u32))
    }

    /// The type with aliases followed to their base.
    pub fn canonical(&self, mut ty: TypeId) -> TypeId {
        for _ in 0..16 {
            match self.info(ty).kind {
                TypeKind::Alias(base) => ty = base,
                _ => return ty,
            }
        }
        ERROR
    }

    /// The type a value of `ty` has in an expression: signals read as their base.
    pub fn value_of(&self, ty: TypeId) -> TypeId {
        let canon = self.canonical(ty);
        match self.info(canon).kind {
            TypeKind::SemiValue(base) => self.canonical(base),
            _ => canon,
        }
    }

    pub fn atomic(&self, ty: TypeId) -> Option<Atomic> {
        match self.info(self.value_of(ty)).kind {
            TypeKind::Atomic(atomic) => Some(atomic),
            _ => None,
        }
    }

    pub fn is_numeric(&self, ty: TypeId) -> bool {
        matches!(self.atomic(ty), Some(Atomic::Num | Atomic::Dnum))
    }

    /// Accepts anything without a further diagnostic.
    pub fn is_lenient(&self, ty: TypeId) -> bool {
        matches!(self.info(self.canonical(ty)).kind, TypeKind::Error | TypeKind::Any | TypeKind::Pending)
    }

    pub fn record_fields(&self, ty: TypeId) -> Option<&[Field]> {
        match &self.info(self.value_of(ty)).kind {
            TypeKind::Record(fields) => Some(fields),
            _ => None,
        }
    }

    pub fn class(&self, ty: TypeId) -> ValueClass {
        // A record is non-value when any component, however deep, is: one walk over
        // the types it reaches, each visited once (records may form cycles, E0509).
        let mut visited: Vec<TypeId> = Vec::new();
        let mut pending = vec![ty];
        let mut class = ValueClass::Value;
        while let Some(next) = pending.pop() {
            let canon = self.canonical(next);
            if visited.contains(&canon) {
                continue;
            }
            visited.push(canon);
            match &self.info(canon).kind {
                TypeKind::NonValue | TypeKind::Switch => return ValueClass::NonValue,
                // Only the type itself being a signal makes data semi-value.
                TypeKind::SemiValue(_) if canon == self.canonical(ty) => class = ValueClass::SemiValue,
                TypeKind::Record(fields) => pending.extend(fields.iter().map(|f| f.ty)),
                _ => {}
            }
        }
        class
    }

    /// Whether a value of type `got` may stand where `want` is expected: alias
    /// equivalence, signals read as their base, num and dnum convert both ways.
    pub fn compatible(&self, want: TypeId, got: TypeId) -> bool {
        if want == got {
            return true;
        }
        if self.is_lenient(want) || self.is_lenient(got) {
            return true;
        }
        let (want_c, got_v) = (self.canonical(want), self.value_of(got));
        want_c == got_v || want_c == self.canonical(got) || (self.is_numeric(want_c) && self.is_numeric(got_v))
    }

    /// Whether `got` is exactly the type `want` up to aliases (for reference parameters).
    pub fn same(&self, want: TypeId, got: TypeId) -> bool {
        want == got || self.is_lenient(want) || self.is_lenient(got) || self.canonical(want) == self.canonical(got)
    }
}

/// Well-known types, found in the catalogue.
#[derive(Debug, Clone, Copy)]
pub struct CoreTypes {
    pub num: TypeId,
    pub dnum: TypeId,
    pub bool_: TypeId,
    pub string: TypeId,
    pub pos: TypeId,
    pub orient: TypeId,
    pub errnum: TypeId,
    pub intnum: TypeId,
}
