//! Case-insensitive interning of identifiers. RAPID ignores letter case, also for the
//! Latin-1 letters, so names are folded to lower case before they are interned.

use rustc_hash::FxHashMap;

/// An interned, case-folded identifier.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Symbol(u32);

impl Symbol {
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// The table of interned names, shared by every file of one check or run.
#[derive(Debug, Default, Clone)]
pub struct Interner {
    map: FxHashMap<Box<str>, Symbol>,
    names: Vec<Box<str>>,
    scratch: String,
}

impl Interner {
    /// Interns `name` case-insensitively.
    pub fn intern(&mut self, name: &str) -> Symbol {
        self.scratch.clear();
        if name.is_ascii() {
            self.scratch.push_str(name);
            self.scratch.make_ascii_lowercase();
        } else {
            self.scratch.extend(name.chars().map(fold_char));
        }
        if let Some(&sym) = self.map.get(self.scratch.as_str()) {
            return sym;
        }
        let sym = Symbol(self.names.len() as u32);
        let key: Box<str> = self.scratch.as_str().into();
        self.names.push(key.clone());
        self.map.insert(key, sym);
        sym
    }

    /// The symbol for `name` if it was interned before.
    pub fn get(&self, name: &str) -> Option<Symbol> {
        let folded: String = name.chars().map(fold_char).collect();
        self.map.get(folded.as_str()).copied()
    }

    /// The folded (lower-case) spelling of a symbol.
    pub fn resolve(&self, sym: Symbol) -> &str {
        &self.names[sym.index()]
    }
}

/// Folds one character the way RAPID compares identifiers: ASCII and the Latin-1
/// capitals À..Þ (except ×) map to their small letters.
pub fn fold_char(c: char) -> char {
    match c {
        'A'..='Z' => c.to_ascii_lowercase(),
        '\u{C0}'..='\u{DE}' if c != '\u{D7}' => char::from_u32(c as u32 + 0x20).unwrap_or(c),
        _ => c,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn case_insensitive_including_latin1() {
        let mut interner = Interner::default();
        let a = interner.intern("MoveAbsJ");
        assert_eq!(a, interner.intern("moveabsj"));
        assert_eq!(interner.intern("ÄRGER"), interner.intern("ärger"));
        assert_ne!(a, interner.intern("MoveL"));
        assert_eq!(interner.resolve(a), "moveabsj");
    }
}
