//! `.pgf` program files. RobotWare writes a small XML file listing the task's modules:
//!
//! ```text
//! <?xml version="1.0" encoding="ISO-8859-1" ?>
//! <Program>
//!     <Module>MainModule.mod</Module>
//!     <Module>Other.mod</Module>
//! </Program>
//! ```
//!
//! Entries are relative to the program file's folder. Some `.pgf` files in the wild hold
//! a module instead (text starting, after an optional `%%%` header and comments, with
//! `MODULE`); those are checked as modules. So is anything that is not an XML listing,
//! so the parser can say what is wrong with it.
//!
//! The listing is read by a small scanner, not an XML library: the format has one
//! element that matters, and the scanner must never fail on malformed input.

use std::fs;
use std::path::{Path, PathBuf};

use rapid_sema::SourceInput;
use rapid_syntax::Span;

/// What a `.pgf` file holds.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum ProgramFile {
    /// A module: check the file itself.
    Module,
    /// The module entries of an XML listing, in file order.
    Listing(Vec<Entry>),
}

/// One `<Module>` entry.
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct Entry {
    /// The entry's text with XML entities decoded and surrounding blanks removed.
    pub(crate) name: String,
    /// Where the name is in the program file (the whole tag for an empty entry).
    pub(crate) span: Span,
}

pub(crate) fn parse(source: &SourceInput) -> ProgramFile {
    if source.unreadable.is_some() || holds_module(&source.text) {
        return ProgramFile::Module;
    }
    match listing(&source.text) {
        Some(entries) => ProgramFile::Listing(entries),
        None => ProgramFile::Module,
    }
}

/// The path of an entry. Tries the name as written, then with Windows separators turned
/// around, then a file of the same name in another letter case: controllers do not care
/// about case, and backups copied to Linux keep whatever case the files happen to have.
pub(crate) fn resolve(folder: &Path, name: &str) -> PathBuf {
    let direct = folder.join(name);
    if direct.exists() {
        return direct;
    }
    let slashed = folder.join(name.replace('\\', "/"));
    if slashed.exists() {
        return slashed;
    }
    find_ignoring_case(&slashed).unwrap_or(direct)
}

fn find_ignoring_case(path: &Path) -> Option<PathBuf> {
    let wanted = path.file_name()?.to_str()?;
    let parent = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    let entries = fs::read_dir(parent).ok()?;
    let found = entries
        .filter_map(Result::ok)
        .find(|entry| entry.file_name().to_str().is_some_and(|name| name.eq_ignore_ascii_case(wanted)))?;
    Some(path.with_file_name(found.file_name()))
}

/// Whether the text is a module: `MODULE` after blanks, a `%%%` header and comments.
fn holds_module(text: &str) -> bool {
    let mut rest = text;
    loop {
        rest = rest.trim_start_matches(|c: char| c.is_whitespace() || c == '\u{feff}');
        if let Some(after) = rest.strip_prefix("%%%") {
            match after.find("%%%") {
                Some(end) => rest = &after[end + 3..],
                None => return false,
            }
        } else if rest.starts_with('!') {
            rest = rest.find('\n').map_or("", |end| &rest[end..]);
        } else {
            break;
        }
    }
    let word_len = rest.bytes().take_while(|b| b.is_ascii_alphanumeric() || *b == b'_').count();
    rest[..word_len].eq_ignore_ascii_case("MODULE")
}

/// The `<Module>` entries of an XML listing, or `None` when the text is not XML.
fn listing(text: &str) -> Option<Vec<Entry>> {
    if !text.trim_start_matches(|c: char| c.is_whitespace() || c == '\u{feff}').starts_with('<') {
        return None;
    }
    let bytes = text.as_bytes();
    let mut entries = Vec::new();
    let mut pos = 0;
    while let Some(found) = text[pos..].find('<') {
        let tag_start = pos + found;
        let rest = &text[tag_start..];
        if rest.starts_with("<!--") {
            pos = skip_past(text, tag_start + 4, "-->");
            continue;
        }
        if rest.starts_with("<?") {
            pos = skip_past(text, tag_start + 2, "?>");
            continue;
        }
        let name_len = rest[1..]
            .bytes()
            .take_while(|b| b.is_ascii_alphanumeric() || matches!(b, b'_' | b'-' | b'.' | b':'))
            .count();
        let tag_name = &rest[1..1 + name_len];
        let tag_end = text[tag_start..].find('>').map_or(text.len(), |end| tag_start + end + 1);
        pos = tag_end;
        if !tag_name.eq_ignore_ascii_case("Module") {
            continue;
        }
        if tag_end >= 2 && bytes[tag_end - 1] == b'>' && bytes[tag_end - 2] == b'/' {
            entries.push(Entry { name: String::new(), span: Span::new(tag_start, tag_end) });
            continue;
        }
        // Text holds no `<`, so the entry runs to the next tag (normally `</Module>`).
        let content_end = text[tag_end..].find('<').map_or(text.len(), |end| tag_end + end);
        let raw = &text[tag_end..content_end];
        let trimmed = raw.trim();
        let name_start = tag_end + (raw.len() - raw.trim_start().len());
        let span = if trimmed.is_empty() {
            Span::new(tag_start, tag_end)
        } else {
            Span::new(name_start, name_start + trimmed.len())
        };
        entries.push(Entry { name: decode_entities(trimmed), span });
        pos = content_end;
    }
    Some(entries)
}

/// The offset just past the first `end` at or after `from`, or the end of the text.
fn skip_past(text: &str, from: usize, end: &str) -> usize {
    text.get(from..).and_then(|rest| rest.find(end)).map_or(text.len(), |at| from + at + end.len())
}

/// Decodes the five named XML entities and numeric character references.
fn decode_entities(raw: &str) -> String {
    let mut res = String::with_capacity(raw.len());
    let mut rest = raw;
    while let Some(amp) = rest.find('&') {
        res.push_str(&rest[..amp]);
        rest = &rest[amp..];
        let Some(semi) = rest.find(';') else { break };
        let decoded = match &rest[1..semi] {
            "amp" => Some('&'),
            "lt" => Some('<'),
            "gt" => Some('>'),
            "quot" => Some('"'),
            "apos" => Some('\''),
            reference => numeric_reference(reference),
        };
        match decoded {
            Some(c) => {
                res.push(c);
                rest = &rest[semi + 1..];
            }
            None => {
                res.push('&');
                rest = &rest[1..];
            }
        }
    }
    res.push_str(rest);
    res
}

fn numeric_reference(reference: &str) -> Option<char> {
    let digits = reference.strip_prefix('#')?;
    let value = match digits.strip_prefix(['x', 'X']) {
        Some(hex) => u32::from_str_radix(hex, 16).ok()?,
        None => digits.parse().ok()?,
    };
    char::from_u32(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_text(text: &str) -> ProgramFile {
        parse(&SourceInput::from_text("p.pgf", text))
    }

    fn names(text: &str) -> Vec<(String, &str)> {
        match parse_text(text) {
            ProgramFile::Listing(entries) => {
                entries.into_iter().map(|entry| (entry.name, entry.span.text(text))).collect()
            }
            ProgramFile::Module => panic!("expected a listing"),
        }
    }

    #[test]
    fn robotware_listing() {
        let text = "<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>\r\n<Program>\r\n\t<Module>MainModule.mod</Module>\r\n\t<Module> Other.mod </Module>\r\n</Program>\r\n";
        assert_eq!(
            names(text),
            vec![("MainModule.mod".to_owned(), "MainModule.mod"), ("Other.mod".to_owned(), "Other.mod")]
        );
    }

    #[test]
    fn comments_entities_and_empty_entries() {
        let text = "<Program><!-- <Module>Old.mod</Module> --><module>R&amp;D.mod</module><Module/><Module></Module></Program>";
        assert_eq!(
            names(text),
            vec![("R&D.mod".to_owned(), "R&amp;D.mod"), (String::new(), "<Module/>"), (String::new(), "<Module>"),]
        );
    }

    #[test]
    fn malformed_listings_do_not_fail() {
        for text in
            ["<", "<Module", "<Module>", "<Module>a.mod", "<!--", "<?xml", "<Program><Module>&#xFFFFFFFF;&#;&</Module>"]
        {
            let _ = parse_text(text);
        }
        assert_eq!(names("<Program><Module>a.mod"), vec![("a.mod".to_owned(), "a.mod")]);
    }

    #[test]
    fn modules_are_recognised() {
        assert_eq!(parse_text("MODULE Main\nENDMODULE"), ProgramFile::Module);
        assert_eq!(parse_text("\u{feff}%%%\n VERSION:1\n%%%\n! note\nmodule Main(SYSMODULE)"), ProgramFile::Module);
        assert_eq!(parse_text("just words"), ProgramFile::Module);
        assert_eq!(parse_text("%%% open header <Program>"), ProgramFile::Module);
        assert_eq!(parse_text("<Program></Program>"), ProgramFile::Listing(Vec::new()));
    }
}
