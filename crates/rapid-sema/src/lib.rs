//! rapid-sema: name resolution, type checking and the diagnostics of `rapid check`.
//!
//! Invariant: no IO. Files arrive as bytes with a display path; diagnostics leave as
//! data (code, span, message) and are rendered by rapid-cli.

pub mod codes;
mod diagnostic;

pub use codes::{Code, Severity};
pub use diagnostic::{Diagnostic, SourceInput};

/// What `check` should do.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Stop after parsing: report lexical and syntax errors only.
    pub syntax_only: bool,
}

/// Checks the modules of one task (one program) together and returns every
/// diagnostic, ordered by file and position.
pub fn check(files: &[SourceInput], options: &Options) -> Vec<Diagnostic> {
    let _ = (files, options);
    Vec::new()
}
