//! Diagnostics as data, and the inputs they point into.

use std::sync::Arc;

use rapid_syntax::source::{decode, Unreadable};
use rapid_syntax::Span;

use crate::codes::{Code, Severity};

/// One file of the program: its display path and decoded text.
///
/// The text is shared, not owned: the front end keeps the files for its messages, the
/// interpreter keeps them to link modules loaded at run time and to serve and save
/// module text, and a clone is a reference count, so a run holds each source once.
/// An `Arc<String>` rather than an `Arc<str>`: the decoded `String` moves in as it is,
/// where an `Arc<str>` would copy it (twice the file's size for a moment).
#[derive(Debug, Clone)]
pub struct SourceInput {
    /// The path as the user should see it in messages.
    pub path: String,
    /// The decoded text (empty when the file could not be read as text).
    pub text: Arc<String>,
    /// Why the bytes are not RAPID text, if they are not.
    pub unreadable: Option<Unreadable>,
}

impl SourceInput {
    /// Decodes a file's bytes (UTF-8, Latin-1 or UTF-16; see `rapid_syntax::source`).
    pub fn from_bytes(path: impl Into<String>, bytes: Vec<u8>) -> SourceInput {
        let path = path.into();
        match decode(bytes) {
            Ok(source) => SourceInput { path, text: Arc::new(source.text), unreadable: None },
            Err(why) => SourceInput { path, text: Arc::default(), unreadable: Some(why) },
        }
    }

    /// A file given as text.
    pub fn from_text(path: impl Into<String>, text: impl Into<String>) -> SourceInput {
        SourceInput { path: path.into(), text: Arc::new(text.into()), unreadable: None }
    }
}

/// One finding: which file, which code, where, and what to tell the user.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Diagnostic {
    /// Index of the file in the slice given to `check`.
    pub file: usize,
    pub code: Code,
    pub span: Span,
    pub message: String,
}

impl Diagnostic {
    pub fn new(file: usize, code: Code, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic { file, code, span, message: message.into() }
    }

    pub fn severity(&self) -> Severity {
        self.code.severity()
    }

    /// `error` or `warning`.
    pub fn severity_word(&self) -> &'static str {
        match self.severity() {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}
