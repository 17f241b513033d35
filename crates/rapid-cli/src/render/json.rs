//! Diagnostics for machines: one JSON array, one object per diagnostic.
//!
//! ```json
//! [
//!   {
//!     "file": "tests/x.mod",
//!     "line": 12,
//!     "column": 5,
//!     "end_line": 12,
//!     "end_column": 8,
//!     "severity": "error",
//!     "code": "E0201",
//!     "message": "undefined data `foo`"
//!   }
//! ]
//! ```
//!
//! Lines and columns are 1-based; columns count characters. `end_*` is the position
//! just past the span, so an empty span has `end == start`. A check of several tasks
//! adds `"tasks": ["T_ROB1", "T_B"]` to a diagnostic of the tasks' modules: the tasks
//! whose check found it (the field is left out where no task is named, so a check of
//! one task prints what it always has). This is the wire format of `--format json`:
//! change it only by adding fields.

use std::io::{self, Write};

use serde::Serialize;

use crate::render::{severity_name, Files, Reported};

#[derive(Debug, Serialize)]
struct JsonDiagnostic<'a> {
    file: &'a str,
    line: u32,
    column: u32,
    end_line: u32,
    end_column: u32,
    severity: &'static str,
    code: &'static str,
    message: &'a str,
    #[serde(skip_serializing_if = "<[String]>::is_empty")]
    tasks: &'a [String],
}

/// Writes the diagnostics as one pretty-printed JSON array and a newline.
pub(crate) fn render(out: &mut dyn Write, files: &Files<'_>, reported: &[Reported]) -> io::Result<()> {
    let objects: Vec<JsonDiagnostic<'_>> = reported
        .iter()
        .map(|Reported { diag, tasks }| {
            let location = files.location(diag);
            JsonDiagnostic {
                file: files.path(diag.file),
                line: location.start.line,
                column: location.start.column,
                end_line: location.end.line,
                end_column: location.end.column,
                severity: severity_name(diag.severity()),
                code: diag.code.as_str(),
                message: &diag.message,
                tasks,
            }
        })
        .collect();
    serde_json::to_writer_pretty(&mut *out, &objects)?;
    writeln!(out)
}

#[cfg(test)]
mod tests {
    use rapid_sema::{Code, Diagnostic, SourceInput};
    use rapid_syntax::Span;

    use super::*;

    fn render_str(sources: &[SourceInput], diagnostics: &[Diagnostic]) -> String {
        render_reported(sources, &Reported::untagged(diagnostics))
    }

    fn render_reported(sources: &[SourceInput], reported: &[Reported]) -> String {
        let table: Vec<&SourceInput> = sources.iter().collect();
        let mut out = Vec::new();
        render(&mut out, &Files::new(&table), reported).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn fields_and_positions() {
        let text = "MODULE m\n  x := \"é\";\n  foo;\nENDMODULE\n";
        let foo = text.find("foo").unwrap();
        let quote = text.find('"').unwrap();
        let diagnostics = [
            Diagnostic::new(0, Code::UndefinedData, Span::new(quote, quote + 4), "a \"quoted\"\nmessage"),
            Diagnostic::new(0, Code::UndefinedProcedure, Span::new(foo, foo + 3), "procedure `foo` is not defined"),
            Diagnostic::new(1, Code::ProgramFileEntry, Span::new(0, 0), "empty"),
        ];
        let sources = [SourceInput::from_text("dir/m.mod", text), SourceInput::from_text("p.pgf", "")];
        let out = render_str(&sources, &diagnostics);
        insta::assert_snapshot!(out);
        let parsed: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(parsed[0]["end_column"], 11, "columns count characters, not bytes");
    }

    #[test]
    fn tasks_are_listed_where_named() {
        let text = "MODULE Lib\n  x := 1;\nENDMODULE\n";
        let x = text.find('x').unwrap();
        let diag = Diagnostic::new(0, Code::UndefinedData, Span::new(x, x + 1), "undefined data `x`");
        let reported =
            [Reported { diag: diag.clone(), tasks: vec!["T_ROB1".to_owned(), "T_B".to_owned()] }, Reported::from(diag)];
        let expected = r#"[
  {
    "file": "Lib.sys",
    "line": 2,
    "column": 3,
    "end_line": 2,
    "end_column": 4,
    "severity": "error",
    "code": "E0201",
    "message": "undefined data `x`",
    "tasks": [
      "T_ROB1",
      "T_B"
    ]
  },
  {
    "file": "Lib.sys",
    "line": 2,
    "column": 3,
    "end_line": 2,
    "end_column": 4,
    "severity": "error",
    "code": "E0201",
    "message": "undefined data `x`"
  }
]
"#;
        assert_eq!(render_reported(&[SourceInput::from_text("Lib.sys", text)], &reported), expected);
    }

    #[test]
    fn no_diagnostics_is_an_empty_array() {
        assert_eq!(render_str(&[], &[]), "[]\n");
    }
}
