//! Runtime errors: a RAPID error number with its predefined name, or a fault of the
//! interpreter's own limits.

use std::fmt;

/// A recoverable RAPID error (ERRNO) or a fatal stop.
#[derive(Debug, Clone, PartialEq)]
pub struct RapidError {
    /// The errnum value (ERRNO); user errors are 1..90.
    pub errno: i32,
    /// The predefined name (`ERR_DIVZERO`), or empty for user and booked numbers.
    pub name: &'static str,
    pub message: String,
    /// Errors that no ERROR handler may take (errors in handlers, limits).
    pub fatal: bool,
    /// The event-log code (domain × 10000 + number) of an error another part of the
    /// controller reports (the motion system's 50050); None: the program domain's, by
    /// `errno`.
    pub event: Option<u32>,
}

impl RapidError {
    pub fn fatal(message: impl Into<String>) -> RapidError {
        RapidError { errno: 0, name: "", message: message.into(), fatal: true, event: None }
    }

    /// A stop the motion system reports as event `code` (50050 Position outside reach).
    pub fn motion(code: u32, message: impl Into<String>) -> RapidError {
        RapidError { event: Some(code), ..RapidError::fatal(message) }
    }
}

impl fmt::Display for RapidError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.name.is_empty(), self.errno) {
            (false, n) => write!(f, "{} ({n}): {}", self.name, self.message),
            (true, 0) => write!(f, "{}", self.message),
            (true, n) => write!(f, "error {n}: {}", self.message),
        }
    }
}
