//! The `.cfg` reader. The format, as RobotWare 6 writes it (read from public
//! backups' `SYSPAR/*.cfg`):
//!
//! ```text
//! EIO:CFG_1.0:6:1::
//! #
//! EIO_SIGNAL:
//!
//!       -Name "di1" -SignalType "DI" -Device "d652"\
//!       -DeviceMap "0"
//! ```
//!
//! The first line names the domain, the format and its version. A `#` line ends one
//! type section; the next `TYPE:` line starts another. Each instance is one logical
//! line of `-Attr value` items; a line ending in `\` continues on the next. Values are
//! quoted strings, bare words (`4`, `-1`, `30,82`) or nothing (a flag such as
//! `-MotionTask`). Blank lines separate instances.
//!
//! The reader never fails: what it cannot read becomes a [`CfgError`] and the rest of
//! the file is kept.

use std::ops::Range;

use crate::{Attr, AttrValue, CfgError, CfgFile, Header, Instance, Section};

/// Parses a `.cfg` file's text.
pub fn parse(text: &str) -> CfgFile {
    let line_starts = std::iter::once(0).chain(text.match_indices('\n').map(|(at, _)| at + 1)).collect();
    let mut reader =
        Reader { file: CfgFile { text: text.to_owned(), ..CfgFile::default() }, seen_content: false, line_starts };
    let lines = physical_lines(text);
    let mut idx = 0;
    while idx < lines.len() {
        let line = lines[idx].clone();
        let trimmed = text[line.clone()].trim();
        if trimmed.is_empty() {
            idx += 1;
            continue;
        }
        if trimmed.starts_with('-') {
            // The instance runs on while lines end in `\`.
            let first = idx;
            if !reader.seen_content {
                let start = line.start + (text[line.clone()].len() - text[line.clone()].trim_start().len());
                reader.error(start..start + trimmed.len(), MISSING_HEADER);
            }
            while idx + 1 < lines.len() && text[lines[idx].clone()].trim_end().ends_with('\\') {
                idx += 1;
            }
            reader.instance(&lines[first..=idx]);
        } else {
            reader.other_line(line, trimmed);
        }
        reader.seen_content = true;
        idx += 1;
    }
    if !reader.seen_content {
        // An empty file says nothing: not even which domain it configures.
        reader.error(0..0, MISSING_HEADER);
    }
    reader.file
}

/// Attributes an instance may give more than once, each time meaning one more value:
/// `-Task "T_ROB1" -Task "T_ROB2"` in `CAB_TASK_MODULES` loads the module into both
/// tasks, as the configuration RobotStudio writes for a module of several tasks does.
// uncertain: the one repeated attribute we have seen in public configurations.
const REPEATABLE: &[&str] = &["Task"];

const MISSING_HEADER: &str = "the file does not start with a header line such as `EIO:CFG_1.0:6:1::`";

struct Reader {
    file: CfgFile,
    /// Whether a non-blank line came before (the header must be the first).
    seen_content: bool,
    /// Where each line starts: a line number is a binary search, not a count from the
    /// top of the file for every instance (quadratic in a file of many instances).
    line_starts: Vec<usize>,
}

impl Reader {
    /// The 1-based line of byte `offset`.
    fn line_of(&self, offset: usize) -> u32 {
        let line = self.line_starts.partition_point(|&start| start <= offset);
        u32::try_from(line).unwrap_or(u32::MAX)
    }

    fn error(&mut self, span: Range<usize>, message: impl Into<String>) {
        let line = self.line_of(span.start);
        self.file.errors.push(CfgError { line, span, message: message.into() });
    }

    /// A line that is not part of an instance: the header, `#`, a comment, a type line.
    fn other_line(&mut self, line: Range<usize>, trimmed: &str) {
        let start = line.start + (self.file.text[line.clone()].len() - self.file.text[line.clone()].trim_start().len());
        let span = start..start + trimmed.len();
        if !self.seen_content {
            if let Some(header) = header(trimmed, span.clone()) {
                self.file.header = Some(header);
                return;
            }
            self.error(span.clone(), MISSING_HEADER);
        }
        if trimmed.starts_with('#') {
            // `#` alone separates sections; `#` and text is a comment.
            // uncertain: RobotWare writes `#` alone; we take any `#` line as a comment.
            return;
        }
        if let Some((label, name)) = type_name(trimmed) {
            self.file.sections.push(Section {
                name: name.to_owned(),
                label: label.map(str::to_owned),
                line: self.line_of(span.start),
                span,
                instances: Vec::new(),
            });
            return;
        }
        if self.seen_content && header(trimmed, span.clone()).is_some() {
            self.error(span, "a header line that is not the file's first line");
            return;
        }
        self.error(span, "expected a type line (`EIO_SIGNAL:`), an instance (`-Name \"...\"`) or `#`");
    }

    /// One instance spread over `lines` (all but the last end in `\`).
    fn instance(&mut self, lines: &[Range<usize>]) {
        let logical = Logical::join(&self.file.text, lines);
        let (attrs, errors) = tokenize(&logical);
        for (span, message) in errors {
            self.error(span, message);
        }
        let start = attrs.first().map_or(lines[0].start, |a| a.name_span.start);
        let last = lines[lines.len() - 1].clone();
        let end = last.start + self.file.text[last].trim_end().len();
        let mut kept: Vec<Attr> = Vec::with_capacity(attrs.len());
        for attr in attrs {
            let repeated = kept.iter().any(|k| k.name.eq_ignore_ascii_case(&attr.name));
            if repeated && !REPEATABLE.iter().any(|r| r.eq_ignore_ascii_case(&attr.name)) {
                let message = format!("attribute `-{}` given twice in one instance; the first is kept", attr.name);
                self.error(attr.name_span.clone(), message);
                continue;
            }
            kept.push(attr);
        }
        let line = self.line_of(start);
        let Some(section) = self.file.sections.last_mut() else {
            self.error(start..end, "an instance before any type line (`EIO_SIGNAL:`); it is ignored");
            return;
        };
        section.instances.push(Instance { line, span: start..end, attrs: kept });
    }
}

/// The lines of `text` without their line ends (`\n` or `\r\n`).
fn physical_lines(text: &str) -> Vec<Range<usize>> {
    let mut lines = Vec::new();
    let mut start = 0;
    for (idx, byte) in text.bytes().enumerate() {
        if byte == b'\n' {
            let end = if idx > start && text.as_bytes()[idx - 1] == b'\r' { idx - 1 } else { idx };
            lines.push(start..end);
            start = idx + 1;
        }
    }
    if start < text.len() {
        lines.push(start..text.len());
    }
    lines
}

/// `EIO:CFG_1.0:6:1::` → domain, format, version. A type line (`EIO_SIGNAL:`) has one
/// colon at its end and is not a header.
fn header(line: &str, span: Range<usize>) -> Option<Header> {
    let mut parts = line.split(':');
    let domain = parts.next()?.trim();
    let format = parts.next()?.trim();
    if domain.is_empty() || format.is_empty() || !is_word(domain) {
        return None;
    }
    let version = parts.map(str::trim).filter(|p| !p.is_empty()).map(str::to_owned).collect();
    Some(Header { domain: domain.to_owned(), format: format.to_owned(), version, span })
}

/// `EIO_SIGNAL:` → (None, `EIO_SIGNAL`); `MMC_MC1 = MMC_PALETTE:` → (`MMC_MC1`,
/// `MMC_PALETTE`): a section of a type with a name of its own.
fn type_name(line: &str) -> Option<(Option<&str>, &str)> {
    let name = line.strip_suffix(':')?.trim_end();
    if let Some((label, ty)) = name.split_once('=') {
        let (label, ty) = (label.trim(), ty.trim());
        return (is_word(label) && is_word(ty)).then_some((Some(label), ty));
    }
    is_word(name).then_some((None, name))
}

fn is_word(s: &str) -> bool {
    let mut chars = s.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// An instance's physical lines joined into one, with the offset in the file of every
/// byte so tokens keep their places.
struct Logical {
    text: String,
    offsets: Vec<usize>,
}

impl Logical {
    fn join(file: &str, lines: &[Range<usize>]) -> Logical {
        let mut logical = Logical { text: String::new(), offsets: Vec::new() };
        for (idx, line) in lines.iter().enumerate() {
            let raw = &file[line.clone()];
            let continued = idx + 1 < lines.len();
            let content = if continued {
                // Drop the trailing `\`; a blank stands in for it so `-A\` + `-B`
                // still splits.
                // uncertain: a quoted value broken by `\` would gain a blank; RobotWare
                // breaks lines between items.
                let body = raw.trim_end();
                &body[..body.len() - 1]
            } else {
                raw
            };
            logical.text.push_str(content);
            logical.offsets.extend((0..content.len()).map(|i| line.start + i));
            if continued {
                logical.text.push(' ');
                logical.offsets.push(line.start + content.len());
            }
        }
        logical
    }

    /// The file span of logical bytes `range`.
    fn span(&self, range: Range<usize>) -> Range<usize> {
        let start = self.offsets.get(range.start).copied().unwrap_or_default();
        let end = match range.end.checked_sub(1).and_then(|last| self.offsets.get(last)) {
            Some(&last) if range.end > range.start => last + 1,
            _ => start,
        };
        start..end
    }
}

type Found = (Vec<Attr>, Vec<(Range<usize>, String)>);

/// Splits a logical line into attributes; what is not an attribute is an error.
fn tokenize(logical: &Logical) -> Found {
    let bytes = logical.text.as_bytes();
    let mut attrs = Vec::new();
    let mut errors = Vec::new();
    let mut pos = skip_blanks(bytes, 0);
    while pos < bytes.len() {
        if !starts_attr(bytes, pos) {
            let end = word_end(bytes, pos);
            let word = &logical.text[pos..end];
            errors.push((logical.span(pos..end), format!("unexpected `{word}`: attributes start with `-` and a name")));
            pos = skip_blanks(bytes, end);
            continue;
        }
        let name_end = name_end(bytes, pos + 1);
        let name = logical.text[pos + 1..name_end].to_owned();
        let name_span = logical.span(pos..name_end);
        let value_start = skip_blanks(bytes, name_end);
        let (value, next) = read_value(logical, value_start, &mut errors);
        attrs.push(Attr { name, name_span, value });
        pos = skip_blanks(bytes, next);
    }
    (attrs, errors)
}

/// The value after an attribute name at `pos`, and where reading goes on.
fn read_value(logical: &Logical, pos: usize, errors: &mut Vec<(Range<usize>, String)>) -> (Option<AttrValue>, usize) {
    let bytes = logical.text.as_bytes();
    if pos >= bytes.len() || starts_attr(bytes, pos) {
        return (None, pos);
    }
    if bytes[pos] == b'"' {
        // uncertain: no escapes inside quotes; RobotWare's values never hold a `"`.
        return match bytes[pos + 1..].iter().position(|&b| b == b'"') {
            Some(len) => {
                let close = pos + 1 + len;
                let text = logical.text[pos + 1..close].to_owned();
                (Some(AttrValue { text, quoted: true, span: logical.span(pos..close + 1) }), close + 1)
            }
            None => {
                let span = logical.span(pos..bytes.len());
                errors.push((span.clone(), "a quoted value without its closing `\"`".to_owned()));
                let text = logical.text[pos + 1..].trim_end().to_owned();
                (Some(AttrValue { text, quoted: true, span }), bytes.len())
            }
        };
    }
    let end = word_end(bytes, pos);
    let text = logical.text[pos..end].to_owned();
    (Some(AttrValue { text, quoted: false, span: logical.span(pos..end) }), end)
}

/// `-` followed by a letter or `_` starts an attribute; `-1` is a value.
fn starts_attr(bytes: &[u8], pos: usize) -> bool {
    bytes.get(pos) == Some(&b'-') && bytes.get(pos + 1).is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_')
}

fn name_end(bytes: &[u8], mut pos: usize) -> usize {
    while pos < bytes.len() && (bytes[pos].is_ascii_alphanumeric() || bytes[pos] == b'_') {
        pos += 1;
    }
    pos
}

fn word_end(bytes: &[u8], mut pos: usize) -> usize {
    while pos < bytes.len() && !bytes[pos].is_ascii_whitespace() {
        pos += 1;
    }
    pos
}

fn skip_blanks(bytes: &[u8], mut pos: usize) -> usize {
    while pos < bytes.len() && bytes[pos].is_ascii_whitespace() {
        pos += 1;
    }
    pos
}
