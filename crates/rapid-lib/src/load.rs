//! Reading the catalogue: every declaration entry is parsed, in one go, as one module
//! of RAPID text, so built-ins get exactly the trees user declarations get.

use rapid_syntax::ast::{Item, Module};
use rapid_syntax::{parse, Interner, SyntaxError};

use crate::catalogue::options::{SoftwareOption, ALL_OPTIONS};
use crate::catalogue::{Entry, EntryKind, ALL_CHAPTERS};

/// One catalogue entry with where to find its parsed declaration.
#[derive(Debug, Clone, Copy)]
pub struct LoadedEntry {
    pub chapter: &'static str,
    pub entry: Entry,
    pub item: BuiltinItem,
    /// The software option that declares it (`None`: RobotWare itself).
    pub option: Option<&'static SoftwareOption>,
}

/// What an entry turned into.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BuiltinItem {
    /// Index into `LoadedCatalogue::module.items`.
    Parsed(usize),
    /// An atomic, non-value, semi-value or opaque type, known by name alone.
    NamedType,
}

/// The whole catalogue, parsed.
#[derive(Debug)]
pub struct LoadedCatalogue {
    /// The RAPID text all declaration entries were joined into.
    pub text: String,
    /// That text parsed as one module.
    pub module: Module,
    pub entries: Vec<LoadedEntry>,
    /// Syntax errors in the catalogue itself (a test keeps this empty).
    pub errors: Vec<SyntaxError>,
}

/// Parses every catalogue entry, interning names into `interner`.
pub fn load(interner: &mut Interner) -> LoadedCatalogue {
    let mut text = String::from("MODULE builtin\n");
    let mut entries = Vec::new();
    let mut n_parsed = 0;
    let base = ALL_CHAPTERS.iter().map(|&(chapter, entries)| (chapter, entries, None));
    let options = ALL_OPTIONS.iter().map(|option| (option.chapter, option.entries, Some(option)));
    for (chapter, chapter_entries, option) in base.chain(options) {
        for &entry in chapter_entries {
            let item = match entry.kind {
                EntryKind::AtomicValue | EntryKind::NonValue | EntryKind::SemiValue | EntryKind::Opaque => {
                    BuiltinItem::NamedType
                }
                _ => {
                    append_declaration(&mut text, entry);
                    n_parsed += 1;
                    BuiltinItem::Parsed(n_parsed - 1)
                }
            };
            entries.push(LoadedEntry { chapter, entry, item, option });
        }
    }
    text.push_str("ENDMODULE\n");
    let mut parsed = parse(&text, interner);
    let module = parsed.file.modules.pop().unwrap_or_else(|| empty_module(interner));
    let mut errors = parsed.errors;
    if module.items.len() != n_parsed {
        errors.push(SyntaxError {
            kind: rapid_syntax::SyntaxErrorKind::UnexpectedToken,
            span: module.span,
            message: format!("catalogue declares {n_parsed} items but {} parsed", module.items.len()),
        });
    }
    LoadedCatalogue { text, module, entries, errors }
}

/// Writes one entry as module-level RAPID; routine headers get an empty body.
fn append_declaration(text: &mut String, entry: Entry) {
    text.push_str(entry.text.trim());
    text.push('\n');
    if entry.kind == EntryKind::Routine {
        let head = entry.text.trim_start();
        let end = if head.starts_with("FUNC") {
            "ENDFUNC"
        } else if head.starts_with("TRAP") {
            "ENDTRAP"
        } else {
            "ENDPROC"
        };
        text.push_str(end);
        text.push('\n');
    }
}

fn empty_module(interner: &mut Interner) -> Module {
    let sym = interner.intern("builtin");
    Module {
        name: rapid_syntax::ast::Name { sym, span: Default::default(), is_placeholder: false },
        attrs: Vec::new(),
        items: Vec::new(),
        arena: Default::default(),
        span: Default::default(),
    }
}

impl LoadedCatalogue {
    /// The parsed item of an entry, if it has one.
    pub fn item(&self, entry: &LoadedEntry) -> Option<&Item> {
        match entry.item {
            BuiltinItem::Parsed(idx) => self.module.items.get(idx),
            BuiltinItem::NamedType => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_syntax::LineIndex;

    #[test]
    fn catalogue_parses() {
        let mut interner = Interner::default();
        let cat = load(&mut interner);
        let index = LineIndex::new(&cat.text);
        let report: Vec<String> = cat
            .errors
            .iter()
            .map(|e| {
                let line = index.line_of(e.span.start);
                format!("{}: {}\n    in: {}", line + 1, e.message, index.line_text(&cat.text, line))
            })
            .collect();
        assert!(report.is_empty(), "catalogue entries that do not parse:\n{}", report.join("\n"));
    }

    #[test]
    fn every_entry_has_a_doc_line() {
        let options = ALL_OPTIONS.iter().map(|o| (o.chapter, o.entries));
        for (chapter, entries) in ALL_CHAPTERS.iter().copied().chain(options) {
            for entry in entries {
                assert!(!entry.doc.trim().is_empty(), "{chapter}: {} has no doc", entry.text);
            }
        }
    }
}
