//! The shape of one catalogue entry: RAPID declaration text plus a doc line.
//!
//! Every predefined type, data object, instruction and function is written as the
//! RAPID declaration a user would write for it (extended where built-ins need more
//! than user code may say), so the same parser reads user code and the catalogue.

/// What kind of predefined thing an entry declares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EntryKind {
    /// `PROC Name(params)` or `FUNC type Name(params)`, with no body.
    ///
    /// Parameter lists use RAPID's own syntax, extended in two ways only built-ins use:
    /// required alternatives (`num Value | dnum DValue`, ABB's `Value | DValue`) and the
    /// type `anytype` (any data type; `anytype Name{*}` accepts an array of any rank).
    Routine,
    /// `RECORD name type comp; ... ENDRECORD` or `ALIAS base name;`.
    TypeDecl,
    /// An atomic value type (`num`, `dnum`, `bool`, `string`): `text` is its name.
    AtomicValue,
    /// A non-value type (`clock`, `iodev`, ...): `text` is its name.
    NonValue,
    /// A semi-value type (the signal types): `text` is `"name base"`, where `base`
    /// is the value type the signal reads as in expressions (`"signaldi dionum"`).
    SemiValue,
    /// A data type of a software option whose components ABB does not publish: `text`
    /// is its name. Data of it may be declared (with any initialiser) and passed;
    /// reading a component is an error that names the option.
    Opaque,
    /// `CONST type name := value;`, `VAR type name;` or `PERS type name := value;`.
    Data,
    /// Like `Data`, but a system variable that programs may read and never write
    /// (`ERRNO`, `INTNO`).
    ReadOnlyData,
}

/// One predefined thing: its declaration in RAPID syntax, one line of documentation,
/// and for a routine what its signature cannot say about how arguments are passed.
#[derive(Debug, Clone, Copy)]
pub struct Entry {
    pub kind: EntryKind,
    pub text: &'static str,
    pub doc: &'static str,
    pub flags: RoutineFlags,
}

/// How a built-in routine takes some of its arguments, beyond what RAPID's parameter
/// syntax can say. Set on an entry with [`Entry::names_data`] and
/// [`Entry::takes_signals`]; the compiler reads them from the routine it calls.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RoutineFlags {
    /// The built-in knows an argument by the name of the data object passed, not only
    /// by its value: a syncident is the same sync point in every task by its name, a
    /// taskid names its task (`T_ROB2Id`), a mecunit is the unit of that name, and
    /// GetDataVal/SetDataVal name data. The call records where each argument came from.
    pub names_data: bool,
    /// Its `anytype` parameters take a signal itself rather than the signal's value
    /// (AliasIO, ValidIO: a signal parameter of a signal type always does).
    pub takes_signals: bool,
    /// The arguments are not checked against the parameters: the routine belongs to a
    /// software option whose full parameter list is not public, so only its name and
    /// its kind (instruction or function) are known (the arguments' own names are
    /// still resolved).
    pub unchecked_args: bool,
    /// Optional arguments the declaration does not list are accepted (their values are
    /// still resolved): the routine belongs to a software option whose manual is not
    /// public, public programs show its required parameters and some of its optional
    /// ones, and the manual may document more. Everything declared is checked.
    pub open_optionals: bool,
}

impl RoutineFlags {
    const NONE: RoutineFlags =
        RoutineFlags { names_data: false, takes_signals: false, unchecked_args: false, open_optionals: false };
}

impl Entry {
    /// The routine knows arguments by the names of the data passed ([`RoutineFlags::names_data`]).
    pub const fn names_data(self) -> Entry {
        Entry { flags: RoutineFlags { names_data: true, ..self.flags }, ..self }
    }

    /// The routine's arguments are not checked ([`RoutineFlags::unchecked_args`]).
    pub const fn unchecked_args(self) -> Entry {
        Entry { flags: RoutineFlags { unchecked_args: true, ..self.flags }, ..self }
    }

    /// Optional arguments it does not declare are accepted ([`RoutineFlags::open_optionals`]).
    pub const fn open_optionals(self) -> Entry {
        Entry { flags: RoutineFlags { open_optionals: true, ..self.flags }, ..self }
    }

    /// The routine's `anytype` parameters take signals themselves ([`RoutineFlags::takes_signals`]).
    pub const fn takes_signals(self) -> Entry {
        Entry { flags: RoutineFlags { takes_signals: true, ..self.flags }, ..self }
    }
}

/// A built-in instruction (`PROC`) or function (`FUNC`).
pub const fn routine(text: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::Routine, text, doc, flags: RoutineFlags::NONE }
}

/// A predefined RECORD or ALIAS type.
pub const fn type_decl(text: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::TypeDecl, text, doc, flags: RoutineFlags::NONE }
}

/// An atomic value type.
pub const fn atomic(name: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::AtomicValue, text: name, doc, flags: RoutineFlags::NONE }
}

/// A non-value type.
pub const fn non_value(name: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::NonValue, text: name, doc, flags: RoutineFlags::NONE }
}

/// A semi-value type: `"name base"`.
pub const fn semi_value(name_and_base: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::SemiValue, text: name_and_base, doc, flags: RoutineFlags::NONE }
}

/// An option's data type whose components are not public.
pub const fn opaque(name: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::Opaque, text: name, doc, flags: RoutineFlags::NONE }
}

/// Predefined data (constants, variables, persistents).
pub const fn data(text: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::Data, text, doc, flags: RoutineFlags::NONE }
}

/// A read-only system variable.
pub const fn read_only(text: &'static str, doc: &'static str) -> Entry {
    Entry { kind: EntryKind::ReadOnlyData, text, doc, flags: RoutineFlags::NONE }
}
