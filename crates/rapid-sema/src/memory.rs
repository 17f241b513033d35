//! The program-memory note (W0706): a task whose program is larger than a controller's
//! program memory holds. Counted in bytes of source text against
//! `rapid_limits::PROGRAM_MEMORY_BYTES` (see there for why that measure and that figure);
//! a warning, because ABB does not publish the figure. `analyze` asks for it, so
//! `rapid check` and `rapid run` note the same programs.

use rapid_syntax::Span;

use crate::codes::Code;
use crate::diagnostic::{Diagnostic, SourceInput};

/// The note for the task made of `files` when their text is over `limit` bytes in all,
/// placed at the start of the largest file (the one to split first).
pub(crate) fn program_memory(files: &[SourceInput], limit: u64) -> Option<Diagnostic> {
    let total: u64 = files.iter().map(|f| f.text.len() as u64).sum();
    if total <= limit {
        return None;
    }
    let largest = files.iter().enumerate().max_by_key(|(i, f)| (f.text.len(), std::cmp::Reverse(*i)))?.0;
    let message = rapid_limits::program_too_large(total);
    Some(Diagnostic::new(largest, Code::ProgramMemoryFull, Span::default(), message))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(name: &str, bytes: usize) -> SourceInput {
        SourceInput::from_text(name, "!".repeat(bytes))
    }

    #[test]
    fn a_program_within_the_limit_has_no_note() {
        assert_eq!(program_memory(&[file("a.mod", 60), file("b.sys", 40)], 100), None);
    }

    #[test]
    fn the_files_of_a_task_count_together_and_the_largest_carries_the_note() {
        let files = [file("a.mod", 30), file("b.mod", 50), file("c.sys", 21)];
        let note = program_memory(&files, 100).expect("101 bytes are over 100");
        assert_eq!(note.file, 1);
        assert_eq!(note.code, Code::ProgramMemoryFull);
        assert!(note.message.starts_with("the task's program is 101 bytes of source text;"), "{}", note.message);
    }

    #[test]
    fn of_two_largest_files_the_first_carries_the_note() {
        let files = [file("a.mod", 10), file("b.mod", 60), file("c.mod", 60)];
        assert_eq!(program_memory(&files, 100).map(|d| d.file), Some(1));
    }
}
