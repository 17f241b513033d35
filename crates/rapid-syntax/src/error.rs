//! Syntax errors. Their codes live in rapid-sema's code table; here they are data.

use crate::span::Span;

/// What went wrong while lexing or parsing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SyntaxErrorKind {
    InvalidCharacter,
    IdentifierTooLong,
    StringTooLong,
    UnterminatedString,
    InvalidStringEscape,
    MalformedNumber,
    NumberOutOfRange,
    NonLatin1Character,
    UnterminatedHeader,
    TooManyErrors,
    UnexpectedToken,
    UnclosedBlock,
    NestingTooDeep,
    ModuleAttributeOrder,
    DuplicateModuleAttribute,
    CompoundInCompactIf,
    ReservedWordAsName,
    TooManyDimensions,
    OutsideModule,
}

/// One syntax error: its kind, where, and a message for people.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SyntaxError {
    pub kind: SyntaxErrorKind,
    pub span: Span,
    pub message: String,
}

/// A file stops reporting after this many errors: past it the input is not RAPID.
pub const MAX_ERRORS_PER_FILE: usize = 100;
