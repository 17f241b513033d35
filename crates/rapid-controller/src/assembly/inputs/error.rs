//! Why a PATH cannot be used at all (missing, unreadable, an unknown extension, a
//! folder without modules): a tool failure, not a finding. What the user is told, and
//! the system's reason when there is one, as a chain of causes the front end prints.

use std::fmt;
use std::io;

/// A PATH that cannot be used: the message names it; `source` is the system's reason.
#[derive(Debug)]
pub struct InputError {
    message: String,
    source: Option<io::Error>,
}

/// Says what went wrong in words, without the OS error number.
pub(super) fn describe_io_error(err: &io::Error) -> String {
    match err.kind() {
        io::ErrorKind::NotFound => "no such file".to_owned(),
        io::ErrorKind::PermissionDenied => "permission denied".to_owned(),
        io::ErrorKind::IsADirectory => "it is a folder".to_owned(),
        _ => err.to_string(),
    }
}

impl InputError {
    /// An error that is its message alone.
    pub(crate) fn new(message: impl Into<String>) -> InputError {
        InputError { message: message.into(), source: None }
    }
}

impl fmt::Display for InputError {
    /// The message; with `{:#}`, followed by its cause (`cannot read `x.mod`: No such
    /// file or directory`), as a one-line error shows the chain.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)?;
        match &self.source {
            Some(source) if f.alternate() => write!(f, ": {source}"),
            _ => Ok(()),
        }
    }
}

impl std::error::Error for InputError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        self.source.as_ref().map(|e| e as &(dyn std::error::Error + 'static))
    }
}

/// What the user was doing when the system failed: `cannot read `x.mod``.
pub(crate) trait Context<T> {
    fn with_context(self, message: impl FnOnce() -> String) -> Result<T, InputError>;
}

impl<T> Context<T> for io::Result<T> {
    fn with_context(self, message: impl FnOnce() -> String) -> Result<T, InputError> {
        self.map_err(|source| InputError { message: message(), source: Some(source) })
    }
}

/// Returns an [`InputError`] of the formatted message.
macro_rules! bail {
    ($($arg:tt)*) => {
        return Err($crate::assembly::inputs::InputError::new(format!($($arg)*)))
    };
}
pub(crate) use bail;
