//! How names are spelled: built-in names as the catalogue declares them, unless the
//! file declares a name of its own that folds to the same text (RAPID compares names
//! ignoring case, and a user's identifier is never respelled).

use std::sync::OnceLock;

use rapid_lib::{BuiltinItem, LoadedCatalogue};
use rapid_syntax::ast::{Item, Module, TypeDefKind};
use rapid_syntax::Interner;
use rustc_hash::{FxHashMap, FxHashSet};

/// Names longer than this are never built-in (and RAPID allows at most 32 characters).
const LONGEST_NAME: usize = 32;

/// The catalogue's spellings, by name folded to ASCII lower case.
#[derive(Debug, Default)]
pub(crate) struct Spellings {
    /// Types, data and routines.
    names: FxHashMap<Box<[u8]>, Box<str>>,
    /// Parameter names of built-in routines (written after `\` in calls).
    params: FxHashMap<Box<[u8]>, Box<str>>,
}

/// The catalogue's spellings, read once per process.
pub(crate) fn spellings() -> &'static Spellings {
    static TABLE: OnceLock<Spellings> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut interner = Interner::default();
        let catalogue = rapid_lib::load(&mut interner);
        Spellings::of(&catalogue)
    })
}

impl Spellings {
    fn of(cat: &LoadedCatalogue) -> Spellings {
        let mut table = Spellings::default();
        let text = cat.text.as_str();
        for entry in &cat.entries {
            match entry.item {
                BuiltinItem::NamedType => {
                    let name = entry.entry.text.split_whitespace().next().unwrap_or("");
                    add(&mut table.names, name);
                }
                BuiltinItem::Parsed(_) => match cat.item(entry) {
                    Some(Item::Type(ty)) => add(&mut table.names, ty.name().span.text(text)),
                    Some(Item::Data(data)) => add(&mut table.names, data.name.span.text(text)),
                    Some(Item::Routine(routine)) => {
                        add(&mut table.names, routine.name.span.text(text));
                        for param in &routine.params {
                            add(&mut table.params, param.name.span.text(text));
                        }
                    }
                    _ => {}
                },
            }
        }
        table
    }

    /// The catalogue's spelling of a name (`after_backslash`: an argument name).
    pub(crate) fn get(&self, word: &str, after_backslash: bool) -> Option<&str> {
        let mut buf = [0u8; LONGEST_NAME];
        let folded = fold(word, &mut buf)?;
        let table = if after_backslash { &self.params } else { &self.names };
        table.get(folded).map(|s| &**s)
    }
}

/// The first spelling of a name wins (a name in two chapters is one name).
fn add(table: &mut FxHashMap<Box<[u8]>, Box<str>>, name: &str) {
    if name.is_empty() || !name.is_ascii() {
        return;
    }
    table.entry(name.to_ascii_lowercase().into_bytes().into()).or_insert_with(|| name.into());
}

/// `word` in ASCII lower case, in `buf`; `None` for a word no built-in can be. The
/// folded name is kept as bytes: it is only a key, and ASCII.
fn fold<'b>(word: &str, buf: &'b mut [u8; LONGEST_NAME]) -> Option<&'b [u8]> {
    if word.len() > LONGEST_NAME || !word.is_ascii() {
        return None;
    }
    let out = &mut buf[..word.len()];
    for (slot, byte) in out.iter_mut().zip(word.bytes()) {
        *slot = byte.to_ascii_lowercase();
    }
    Some(out)
}

/// The names a file declares (folded), which are never respelled.
#[derive(Debug, Default)]
pub(crate) struct Declared(FxHashSet<Box<[u8]>>);

impl Declared {
    pub(crate) fn add(&mut self, name: &str) {
        let mut buf = [0u8; LONGEST_NAME];
        if let Some(folded) = fold(name, &mut buf) {
            self.0.insert(folded.into());
        }
    }

    /// Every name a module's outline declares: the module, types and their
    /// components, data, routines and their parameters.
    pub(crate) fn add_outline(&mut self, module: &Module, text: &str) {
        self.add(module.name.span.text(text));
        for item in &module.items {
            match item {
                Item::Type(ty) => {
                    self.add(ty.name().span.text(text));
                    if let TypeDefKind::Record { components, .. } = &ty.kind {
                        for comp in components {
                            self.add(comp.name.span.text(text));
                        }
                    }
                }
                Item::Data(data) => self.add(data.name.span.text(text)),
                Item::Routine(routine) => {
                    self.add(routine.name.span.text(text));
                    for param in &routine.params {
                        self.add(param.name.span.text(text));
                    }
                }
                Item::Placeholder(..) => {}
            }
        }
    }

    /// Adds every name of `other`.
    pub(crate) fn merge(&mut self, other: Declared) {
        self.0.extend(other.0);
    }

    pub(crate) fn contains(&self, word: &str) -> bool {
        let mut buf = [0u8; LONGEST_NAME];
        fold(word, &mut buf).is_some_and(|folded| self.0.contains(folded))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_in_names_are_spelled_as_declared() {
        let table = spellings();
        assert_eq!(table.get("movel", false), Some("MoveL"));
        assert_eq!(table.get("ROBTARGET", false), Some("robtarget"));
        assert_eq!(table.get("tpwrite", false), Some("TPWrite"));
        assert_eq!(table.get("wobj", true), Some("WObj"));
        assert_eq!(table.get("my_proc", false), None);
        assert_eq!(table.get("Ärger", false), None);
    }

    #[test]
    fn declared_names_fold() {
        let mut declared = Declared::default();
        declared.add("MoveL");
        assert!(declared.contains("movel"));
        assert!(!declared.contains("movej"));
    }
}
