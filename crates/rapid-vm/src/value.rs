//! Values as the controller holds them (§1.2): num is an IEEE single, dnum a double,
//! strings at most 80 Latin-1 characters, records and arrays with value semantics.

use rapid_sema::types::TypeId;

/// Strings may hold at most this many characters (§1.1.2).
pub const MAX_STRING_CHARS: usize = rapid_limits::STRING_CHARS;

/// A RAPID value. Cloning copies, as assignment does in RAPID.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Num(f32),
    Dnum(f64),
    Bool(bool),
    /// Characters are Latin-1 code points (U+0000..U+00FF).
    Str(std::rc::Rc<str>),
    Record(std::rc::Rc<Record>),
    Array(Box<Array>),
    /// Data of a non-value type (clock, iodev, ...), which only built-ins touch.
    Opaque(Box<Opaque>),
    /// An optional argument that was not passed.
    Absent,
    /// A switch argument that was passed.
    SwitchOn,
    /// A VAR, INOUT or PERS argument: where the caller's data lives.
    Ref(Box<Place>),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub ty: TypeId,
    pub fields: Vec<Value>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Array {
    /// Sizes of the dimensions (rank = number of non-zero sizes).
    pub dims: [u32; 3],
    pub elems: Vec<Value>,
}

impl Array {
    pub fn rank(&self) -> u8 {
        self.dims.iter().take_while(|&&d| d > 0).count() as u8
    }
}

/// Non-value data: only its type and the state built-ins keep in it.
#[derive(Debug, Clone, PartialEq)]
pub struct Opaque {
    pub ty: TypeId,
    pub state: OpaqueState,
}

#[derive(Debug, Clone, PartialEq)]
pub enum OpaqueState {
    None,
    /// A clock: accumulated seconds and, while running, the start time.
    Clock {
        accumulated: f64,
        started_at: Option<f64>,
    },
    /// A rawbytes: its valid bytes (at most 1024).
    RawBytes(Vec<u8>),
    /// An iodev, dir or socketdev: the number of its entry in the owning family's
    /// table in [`crate::builtins::Resources`].
    Handle(u32),
}

/// Where a data object (or a part of it) lives.
#[derive(Debug, Clone, PartialEq)]
pub struct Place {
    pub root: Root,
    pub path: Vec<PathStep>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Root {
    Global(u32),
    /// An absolute index into the value stack (a slot of some frame).
    Stack(u32),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathStep {
    Field(u16),
    /// A flat element index, already bounds-checked.
    Element(u32),
}

impl Value {
    pub fn is_absent(&self) -> bool {
        matches!(self, Value::Absent)
    }

    /// Follows one step of a path.
    pub fn step(&self, step: PathStep) -> Option<&Value> {
        match (self, step) {
            (Value::Record(r), PathStep::Field(i)) => r.fields.get(i as usize),
            (Value::Array(a), PathStep::Element(i)) => a.elems.get(i as usize),
            _ => None,
        }
    }

    pub fn step_mut(&mut self, step: PathStep) -> Option<&mut Value> {
        match (self, step) {
            (Value::Record(r), PathStep::Field(i)) => std::rc::Rc::make_mut(r).fields.get_mut(i as usize),
            (Value::Array(a), PathStep::Element(i)) => a.elems.get_mut(i as usize),
            _ => None,
        }
    }

    /// The numeric value of a num or dnum.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Num(v) => Some(f64::from(*v)),
            Value::Dnum(v) => Some(*v),
            _ => None,
        }
    }
}

/// The number of characters of a RAPID string.
pub fn string_len(s: &str) -> usize {
    s.chars().count()
}
