//! Diagnostics for people, in the shape of rustc and ruff:
//!
//! ```text
//! error[E0201]: undefined data `foo`
//!   --> tests/x.mod:12:5
//!    |
//! 12 |     foo := 1;
//!    |     ^^^
//! ```
//!
//! A diagnostic of a check of several tasks ends with a note naming the tasks whose
//! check found it (one report for all of them):
//!
//! ```text
//!    |     ^^^
//!    |
//!    = note: in tasks T_ROB1, T_B
//! ```
//!
//! Carets cover the span on its first line (at least one caret). The source line is
//! made safe for a terminal: tabs become four spaces, control characters become visible
//! symbols, and a line longer than [`LONG_LINE`] characters is cut to a window of about
//! [`WINDOW`] characters around the caret, marked with `...`.

use std::io::{self, Write};

use crate::render::{severity_name, Files, Reported, Summary};

/// Lines longer than this many characters are shown as a window around the caret.
pub(crate) const LONG_LINE: usize = 200;
/// How many characters of a long line are shown.
pub(crate) const WINDOW: usize = 120;
/// How many of them come before the caret.
const WINDOW_LEAD: usize = 40;
/// Spaces that stand for a tab.
const TAB_WIDTH: usize = 4;

/// Writes every diagnostic, then the summary line.
pub(crate) fn render(
    out: &mut dyn Write,
    files: &Files<'_>,
    reported: &[Reported],
    summary: &Summary,
) -> io::Result<()> {
    for it in reported {
        render_one(out, files, it)?;
        writeln!(out)?;
    }
    write_summary(out, summary)
}

/// Writes one diagnostic: header, location, the excerpt with carets and the tasks.
pub(crate) fn render_one(out: &mut dyn Write, files: &Files<'_>, reported: &Reported) -> io::Result<()> {
    let diag = &reported.diag;
    let severity = severity_name(diag.severity());
    writeln!(out, "{severity}[{}]: {}", diag.code.as_str(), sanitize(&diag.message))?;

    let location = files.location(diag);
    let line_no = location.start.line.to_string();
    let gutter = " ".repeat(line_no.len());
    writeln!(out, "{gutter}--> {}:{}:{}", files.path(diag.file), location.start.line, location.start.column)?;

    let text = files.text(diag.file);
    let (start, end) = files.offsets(diag);
    let line_start = text[..start].rfind('\n').map_or(0, |idx| idx + 1);
    let line_end = text[start..].find('\n').map_or(text.len(), |idx| start + idx);
    let line = text[line_start..line_end].trim_end_matches('\r');
    let caret_start = (start - line_start).min(line.len());
    let caret_end = (end.min(line_end) - line_start).clamp(caret_start, line.len());
    let excerpt = excerpt(line, caret_start, caret_end);

    writeln!(out, "{gutter} |")?;
    writeln!(out, "{line_no} | {}", excerpt.text.trim_end())?;
    let pad = " ".repeat(excerpt.caret_column);
    writeln!(out, "{gutter} | {pad}{}", "^".repeat(excerpt.caret_width))?;
    let word = match reported.tasks.len() {
        0 => return Ok(()),
        1 => "task",
        _ => "tasks",
    };
    writeln!(out, "{gutter} |")?;
    writeln!(out, "{gutter} = note: in {word} {}", sanitize(&reported.tasks.join(", ")))
}

/// `found 2 errors and 1 warning in 3 files`, or `checked 3 files: no problems found`.
pub(crate) fn write_summary(out: &mut dyn Write, summary: &Summary) -> io::Result<()> {
    let files = plural(summary.files, "file");
    if summary.errors == 0 && summary.warnings == 0 {
        return writeln!(out, "checked {files}: no problems found");
    }
    let errors = plural(summary.errors, "error");
    let warnings = plural(summary.warnings, "warning");
    writeln!(out, "found {errors} and {warnings} in {files}")
}

fn plural(count: usize, noun: &str) -> String {
    match count {
        1 => format!("1 {noun}"),
        _ => format!("{count} {noun}s"),
    }
}

/// A source line ready to print, and where its carets go (in display columns).
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct Excerpt {
    pub(crate) text: String,
    pub(crate) caret_column: usize,
    pub(crate) caret_width: usize,
}

/// Prepares `line` for display with carets under the bytes `start..end`
/// (`start <= end <= line.len()`, both on character boundaries).
pub(crate) fn excerpt(line: &str, start: usize, end: usize) -> Excerpt {
    let is_long = line.len() > LONG_LINE && line.chars().take(LONG_LINE + 1).count() > LONG_LINE;
    let (window_start, window_end) = if is_long {
        let window_start = line[..start].char_indices().rev().nth(WINDOW_LEAD - 1).map_or(0, |(idx, _)| idx);
        let window_end =
            line[window_start..].char_indices().nth(WINDOW).map_or(line.len(), |(idx, _)| window_start + idx);
        (window_start, window_end)
    } else {
        (0, line.len())
    };

    let mut text = String::new();
    let mut column = 0;
    if window_start > 0 {
        text.push_str("...");
        column += 3;
    }
    let mut caret_column = None;
    let mut caret_end_column = None;
    for (idx, c) in line[window_start..window_end].char_indices() {
        let idx = window_start + idx;
        if idx == start {
            caret_column = Some(column);
        }
        if idx == end {
            caret_end_column = Some(column);
        }
        column += push_display(&mut text, c);
    }
    let caret_column = caret_column.unwrap_or(column);
    let caret_end_column = caret_end_column.unwrap_or(column);
    if window_end < line.len() {
        text.push_str("...");
    }
    Excerpt { text, caret_column, caret_width: caret_end_column.saturating_sub(caret_column).max(1) }
}

/// Appends how `c` should look in a terminal and returns how many columns that takes.
fn push_display(out: &mut String, c: char) -> usize {
    match c {
        '\t' => {
            out.push_str(&" ".repeat(TAB_WIDTH));
            TAB_WIDTH
        }
        _ => {
            let shown = visible(c);
            out.push(shown);
            char_width(shown)
        }
    }
}

/// Replaces characters that a terminal would act on instead of showing: C0 controls
/// become the Unicode control pictures (`␀`, `␛`, …); DEL, C1 controls and bidirectional
/// overrides become `�`.
fn visible(c: char) -> char {
    match c {
        '\0'..='\u{1f}' => char::from_u32(0x2400 + c as u32).unwrap_or('\u{fffd}'),
        '\u{7f}'..='\u{9f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' => '\u{fffd}',
        _ => c,
    }
}

/// Makes a message safe to print on one line.
fn sanitize(message: &str) -> String {
    message.chars().map(|c| if c == '\t' { ' ' } else { visible(c) }).collect()
}

/// Terminal columns a character takes: 0 for combining marks and zero-width characters,
/// 2 for East Asian wide characters, 1 otherwise. An approximation of Unicode's
/// East Asian Width table that covers what RAPID files hold (Latin-1, with comments
/// in any language).
fn char_width(c: char) -> usize {
    match c {
        '\u{0300}'..='\u{036f}' | '\u{200b}'..='\u{200f}' | '\u{feff}' => 0,
        '\u{1100}'..='\u{115f}'
        | '\u{2e80}'..='\u{303e}'
        | '\u{3041}'..='\u{33ff}'
        | '\u{3400}'..='\u{4dbf}'
        | '\u{4e00}'..='\u{9fff}'
        | '\u{a000}'..='\u{a4cf}'
        | '\u{ac00}'..='\u{d7a3}'
        | '\u{f900}'..='\u{faff}'
        | '\u{fe30}'..='\u{fe4f}'
        | '\u{ff00}'..='\u{ff60}'
        | '\u{ffe0}'..='\u{ffe6}'
        | '\u{1f300}'..='\u{1f64f}'
        | '\u{1f900}'..='\u{1f9ff}'
        | '\u{20000}'..='\u{3fffd}' => 2,
        _ => 1,
    }
}

#[cfg(test)]
mod tests {
    use rapid_sema::{Code, Diagnostic, SourceInput};
    use rapid_syntax::Span;

    use super::*;

    /// Renders diagnostics given as (file, code, start, end, message) over the files.
    fn render_str(sources: &[SourceInput], diags: &[(usize, Code, usize, usize, &str)]) -> String {
        let reported: Vec<Reported> = diags
            .iter()
            .map(|&(file, code, start, end, message)| Diagnostic::new(file, code, Span::new(start, end), message))
            .map(Reported::from)
            .collect();
        render_reported(sources, &reported)
    }

    fn render_reported(sources: &[SourceInput], reported: &[Reported]) -> String {
        let table: Vec<&SourceInput> = sources.iter().collect();
        let files = Files::new(&table);
        let summary = Summary::of(reported, &files);
        let mut out = Vec::new();
        render(&mut out, &files, reported, &summary).unwrap();
        String::from_utf8(out).unwrap()
    }

    fn span_of(text: &str, needle: &str) -> (usize, usize) {
        let start = text.find(needle).unwrap();
        (start, start + needle.len())
    }

    #[test]
    fn error_and_warning() {
        let text = "MODULE m\n    PROC main()\n        foo := 1;\n        nosuch;\n    ENDPROC\nENDMODULE\n";
        let source = SourceInput::from_text("tests/x.mod", text);
        let (a, b) = span_of(text, "foo");
        let (c, d) = span_of(text, "nosuch");
        let out = render_str(
            &[source],
            &[
                (0, Code::UndefinedData, a, b, "undefined data `foo`"),
                (0, Code::UndefinedProcedure, c, d, "procedure `nosuch` is not defined in the task"),
            ],
        );
        insta::assert_snapshot!(out);
    }

    #[test]
    fn tasks_are_named_in_a_note() {
        // One library module loaded in two tasks: in the table once for each task, so
        // the summary counts one file. Line 3 of the module, column 3, gutter of one.
        let text = "MODULE Lib\n  PROC p()\n  x := 1;\n  ENDPROC\nENDMODULE\n";
        let sources = [SourceInput::from_text("lib/Lib.sys", text), SourceInput::from_text("lib/Lib.sys", text)];
        let (a, b) = span_of(text, "x");
        let undefined = |file| Diagnostic::new(file, Code::UndefinedData, Span::new(a, b), "undefined data `x`");
        let reported = [
            Reported { diag: undefined(0), tasks: vec!["T_ROB1".to_owned(), "T_B".to_owned()] },
            Reported { diag: undefined(1), tasks: vec!["T_B".to_owned()] },
        ];
        let expected = "\
error[E0201]: undefined data `x`
 --> lib/Lib.sys:3:3
  |
3 |   x := 1;
  |   ^
  |
  = note: in tasks T_ROB1, T_B

error[E0201]: undefined data `x`
 --> lib/Lib.sys:3:3
  |
3 |   x := 1;
  |   ^
  |
  = note: in task T_B

found 2 errors and 0 warnings in 1 file
";
        assert_eq!(render_reported(&sources, &reported), expected);
    }

    #[test]
    fn clean_summary() {
        let source = SourceInput::from_text("a.mod", "MODULE a\nENDMODULE\n");
        assert_eq!(render_str(&[source], &[]), "checked 1 file: no problems found\n");
    }

    #[test]
    fn wide_gutter_empty_span_and_line_end() {
        let mut text = "\n".repeat(99);
        text.push_str("VAR num x := ;\r\n");
        let (semi, _) = span_of(&text, ";");
        let source = SourceInput::from_text("m.mod", text.clone());
        let out = render_str(
            &[source],
            &[
                (0, Code::UnexpectedToken, semi, semi, "expected an expression, found `;`"),
                (0, Code::UnclosedBlock, text.len() - 2, text.len() + 5, "past the end"),
            ],
        );
        insta::assert_snapshot!(out);
    }

    #[test]
    fn multi_line_span_stops_at_line_end() {
        let text = "IF a THEN\n  b;\nENDIF";
        let source = SourceInput::from_text("m.mod", text);
        let out = render_str(&[source], &[(0, Code::UnclosedBlock, 0, text.len(), "IF without ENDIF")]);
        insta::assert_snapshot!(out);
    }

    #[test]
    fn tabs_controls_and_wide_characters() {
        let text = "\tVAR\tnum x:=\u{1b}[31m; ! 注释 \u{0}\n";
        let source = SourceInput::from_text("t.mod", text);
        let (a, b) = span_of(text, "\u{1b}");
        let out = render_str(&[source], &[(0, Code::InvalidCharacter, a, b, "invalid character `\u{1b}`\tthere")]);
        insta::assert_snapshot!(out);
        let (c, _) = span_of(text, "\u{0}");
        let shown = excerpt(text.trim_end(), c, c + 1);
        // Tab (4) + "VAR" + tab (4) + "num x:=␛[31m; ! " + two wide characters + space.
        assert_eq!(shown.caret_column, 4 + 3 + 4 + 16 + 4 + 1);
    }

    #[test]
    fn long_line_is_windowed() {
        let mut line = "x".repeat(5000);
        line.replace_range(2500..2503, "bad");
        let text = format!("MODULE m\n{line}\nENDMODULE\n");
        let (a, b) = span_of(&text, "bad");
        let source = SourceInput::from_text("long.mod", text.clone());
        let out = render_str(&[source], &[(0, Code::UnexpectedToken, a, b, "unexpected `bad`")]);
        assert!(out.len() < 600, "output too long: {} bytes", out.len());
        insta::assert_snapshot!(out);
    }

    #[test]
    fn long_line_window_at_both_ends() {
        let line = "a".repeat(300);
        let head = excerpt(&line, 0, 1);
        assert_eq!(head.caret_column, 0);
        assert!(head.text.ends_with("...") && !head.text.starts_with("..."));
        assert_eq!(head.text.len(), WINDOW + 3);
        let tail = excerpt(&line, 300, 300);
        assert!(tail.text.starts_with("...") && !tail.text.ends_with("..."));
        assert_eq!(tail.caret_column, tail.text.len());
        assert_eq!(tail.caret_width, 1);
        let whole = excerpt(&line, 10, 300);
        assert_eq!(whole.caret_column, 10);
        assert_eq!(whole.caret_width, WINDOW - 10);
    }

    #[test]
    fn every_offset_of_awkward_text_renders() {
        let text = "é\t\u{0}注\r\n\r\n\u{1b}x\u{feff}\u{10ffff}\n".to_owned() + &"ü".repeat(300);
        let source = SourceInput::from_text("w.mod", text.clone());
        let table = [&source];
        let files = Files::new(&table);
        for start in 0..text.len() + 2 {
            for end in [0, start, start + 1, start + 7, text.len() + 3] {
                let diag = Diagnostic::new(0, Code::UnexpectedToken, Span::new(start, end), "m");
                let mut out = Vec::new();
                render_one(&mut out, &files, &Reported::from(diag)).unwrap();
                let shown = String::from_utf8(out).unwrap();
                assert!(shown.lines().count() == 5 && shown.contains('^'), "{shown}");
                assert!(shown.len() < 1000, "{shown}");
            }
        }
    }
}
