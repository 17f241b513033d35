//! Turning diagnostics into what users read: text with source excerpts, JSON, or a
//! SARIF log for code-scanning services.
//!
//! Diagnostics carry byte spans; lines and columns are computed here, only for the
//! files that have something to report. The renderers never panic: a span past the end
//! of its text or inside a character is pulled back to the nearest character boundary.
//!
//! A check of several tasks reports each diagnostic of a task's modules with the tasks
//! whose check found it ([`Reported::tasks`]), so a module loaded in several tasks has
//! one report per problem that says where it holds.

pub(crate) mod human;
pub(crate) mod json;
pub(crate) mod sarif;

use std::cell::OnceCell;

use rapid_sema::{Diagnostic, Severity, SourceInput};
use rapid_syntax::{LineCol, LineIndex};
use rustc_hash::FxHashSet;

/// The files diagnostics point into, with line indexes built on first use.
pub(crate) struct Files<'a> {
    sources: &'a [&'a SourceInput],
    line_indexes: Vec<OnceCell<LineIndex>>,
}

/// A diagnostic as reported: with the names of the tasks whose check found it, in the
/// order they were checked. Empty when the check covers one task, and for findings
/// about the system or its configuration as a whole.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Reported {
    pub(crate) diag: Diagnostic,
    pub(crate) tasks: Vec<String>,
}

impl Reported {
    /// Diagnostics that no task is named for.
    pub(crate) fn untagged(diagnostics: &[Diagnostic]) -> Vec<Reported> {
        diagnostics.iter().cloned().map(Reported::from).collect()
    }
}

impl From<Diagnostic> for Reported {
    fn from(diag: Diagnostic) -> Reported {
        Reported { diag, tasks: Vec::new() }
    }
}

/// Where a diagnostic starts and ends, as 1-based lines and character columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Location {
    pub(crate) start: LineCol,
    pub(crate) end: LineCol,
}

impl<'a> Files<'a> {
    pub(crate) fn new(sources: &'a [&'a SourceInput]) -> Files<'a> {
        Files { sources, line_indexes: sources.iter().map(|_| OnceCell::new()).collect() }
    }

    /// How many different files the table holds: a file that several tasks load is
    /// in the table once for each, under one path.
    pub(crate) fn distinct(&self) -> usize {
        self.sources.iter().map(|source| source.path.as_str()).collect::<FxHashSet<_>>().len()
    }

    /// The path to show for a file.
    pub(crate) fn path(&self, file: usize) -> &str {
        self.sources.get(file).map_or("<unknown file>", |source| &source.path)
    }

    /// The text of a file (empty for a file the checker does not know).
    pub(crate) fn text(&self, file: usize) -> &str {
        self.sources.get(file).map_or("", |source| &source.text)
    }

    pub(crate) fn line_index(&self, file: usize) -> Option<&LineIndex> {
        let cell = self.line_indexes.get(file)?;
        Some(cell.get_or_init(|| LineIndex::new(self.text(file))))
    }

    /// The start and end of a diagnostic's span.
    pub(crate) fn location(&self, diag: &Diagnostic) -> Location {
        let (start, end) = self.offsets(diag);
        let text = self.text(diag.file);
        match self.line_index(diag.file) {
            Some(index) => {
                Location { start: index.line_col(text, start as u32), end: index.line_col(text, end as u32) }
            }
            None => {
                let origin = LineCol { line: 1, column: 1 };
                Location { start: origin, end: origin }
            }
        }
    }

    /// The span's byte offsets, made safe to slice the file's text with.
    pub(crate) fn offsets(&self, diag: &Diagnostic) -> (usize, usize) {
        let text = self.text(diag.file);
        let start = floor_char_boundary(text, diag.span.start as usize);
        let end = floor_char_boundary(text, diag.span.end as usize).max(start);
        (start, end)
    }
}

/// How many errors and warnings a run found, and in how many files (by path).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Summary {
    pub(crate) errors: usize,
    pub(crate) warnings: usize,
    pub(crate) files: usize,
}

impl Summary {
    pub(crate) fn of(reported: &[Reported], files: &Files<'_>) -> Summary {
        let errors = reported.iter().filter(|it| it.diag.severity() == Severity::Error).count();
        Summary { errors, warnings: reported.len() - errors, files: files.distinct() }
    }
}

/// `error` or `warning`, as printed in both formats.
pub(crate) fn severity_name(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
    }
}

/// The largest character boundary at or before `offset`, and never past the end.
fn floor_char_boundary(text: &str, offset: usize) -> usize {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

#[cfg(test)]
mod tests {
    use rapid_sema::Code;
    use rapid_syntax::Span;

    use super::*;

    #[test]
    fn spans_out_of_range_are_clamped() {
        let source = SourceInput::from_text("a.mod", "é\nx");
        let table = [&source];
        let files = Files::new(&table);
        let diag = |start, end| Diagnostic::new(0, Code::UndefinedData, Span { start, end }, "m");
        assert_eq!(files.offsets(&diag(1, 2)), (0, 2));
        assert_eq!(files.offsets(&diag(3, 100)), (3, 4));
        assert_eq!(files.offsets(&diag(9, 2)), (4, 4));
        let location = files.location(&diag(3, 100));
        assert_eq!(location.start, LineCol { line: 2, column: 1 });
        assert_eq!(location.end, LineCol { line: 2, column: 2 });
        let unknown = Diagnostic::new(7, Code::UndefinedData, Span { start: 5, end: 6 }, "m");
        assert_eq!(files.path(7), "<unknown file>");
        assert_eq!(files.location(&unknown).start, LineCol { line: 1, column: 1 });
    }
}
