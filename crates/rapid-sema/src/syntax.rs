//! Syntax errors from rapid-syntax, given their codes.

use rapid_syntax::{SyntaxError, SyntaxErrorKind as K};

use crate::codes::Code;
use crate::diagnostic::Diagnostic;

pub(crate) fn to_diagnostic(file: usize, error: &SyntaxError) -> Diagnostic {
    Diagnostic::new(file, code_of(error.kind), error.span, error.message.clone())
}

fn code_of(kind: K) -> Code {
    match kind {
        K::InvalidCharacter => Code::InvalidCharacter,
        K::IdentifierTooLong => Code::IdentifierTooLong,
        K::StringTooLong => Code::StringTooLong,
        K::UnterminatedString => Code::UnterminatedString,
        K::InvalidStringEscape => Code::InvalidStringEscape,
        K::MalformedNumber => Code::MalformedNumber,
        K::NumberOutOfRange => Code::NumberOutOfRange,
        K::NonLatin1Character => Code::NonLatin1Character,
        K::UnterminatedHeader => Code::UnterminatedHeader,
        K::TooManyErrors => Code::TooManyErrors,
        K::UnexpectedToken => Code::UnexpectedToken,
        K::UnclosedBlock => Code::UnclosedBlock,
        K::NestingTooDeep => Code::NestingTooDeep,
        K::ModuleAttributeOrder => Code::ModuleAttributeOrder,
        K::DuplicateModuleAttribute => Code::DuplicateModuleAttribute,
        K::CompoundInCompactIf => Code::CompoundInCompactIf,
        K::ReservedWordAsName => Code::ReservedWordAsName,
        K::TooManyDimensions => Code::TooManyDimensions,
        K::OutsideModule => Code::OutsideModule,
    }
}
