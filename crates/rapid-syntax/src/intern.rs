//! Case-insensitive interning of identifiers. RAPID ignores letter case, also for the
//! Latin-1 letters, so names are folded to lower case before they are interned.

use std::sync::Arc;

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
///
/// Its names may start with a frozen, shared prefix ([`Interner::freeze`]): the
/// catalogue's names, interned once per process, which every check starts from.
/// Cloning then copies only the names interned since, not one allocation per
/// catalogue name (and dropping frees only those).
#[derive(Debug, Default, Clone)]
pub struct Interner {
    /// Symbols `0..base.names.len()`, shared.
    base: Arc<Table>,
    /// Symbols from `base.names.len()` on.
    own: Table,
    scratch: String,
}

/// How many names added to a shared prefix [`Interner::freeze`] leaves as they are.
const FEW: usize = 32;

#[derive(Debug, Default, Clone)]
struct Table {
    map: FxHashMap<Box<str>, Symbol>,
    names: Vec<Box<str>>,
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
        if let Some(sym) = self.lookup(&self.scratch) {
            return sym;
        }
        let sym = Symbol((self.base.names.len() + self.own.names.len()) as u32);
        let key: Box<str> = self.scratch.as_str().into();
        self.own.names.push(key.clone());
        self.own.map.insert(key, sym);
        sym
    }

    /// The symbol for `name` if it was interned before.
    pub fn get(&self, name: &str) -> Option<Symbol> {
        // Most names asked for are short ASCII (a loader asks for each of the 300
        // ERR_ names): folded on the stack, without an allocation.
        let mut buf = [0u8; 48];
        if name.is_ascii() && name.len() <= buf.len() {
            let folded = &mut buf[..name.len()];
            folded.copy_from_slice(name.as_bytes());
            folded.make_ascii_lowercase();
            return std::str::from_utf8(folded).ok().and_then(|folded| self.lookup(folded));
        }
        let folded: String = name.chars().map(fold_char).collect();
        self.lookup(&folded)
    }

    /// The folded (lower-case) spelling of a symbol.
    pub fn resolve(&self, sym: Symbol) -> &str {
        match sym.index().checked_sub(self.base.names.len()) {
            Some(own) => &self.own.names[own],
            None => &self.base.names[sym.index()],
        }
    }

    /// The same names and symbols, every name now in the shared prefix: clones of
    /// the result (each check's starting interner) share them instead of copying —
    /// except at most [`FEW`] names added to a prefix still shared, which stay the
    /// interner's own (copying the prefix to add them would cost more than a clone
    /// copying them).
    pub fn freeze(self) -> Interner {
        if self.own.names.is_empty() {
            return self;
        }
        // The first freeze (the catalogue's names, once per process): the own table,
        // numbered from 0, is the prefix as it is. Rebuilding it name by name cost 13 %
        // of a one-line program's `rapid run` (callgrind, bench/interp startup).
        if self.base.names.is_empty() {
            return Interner { base: Arc::new(self.own), own: Table::default(), scratch: String::new() };
        }
        // A prefix another interner shares would be copied whole to grow it (the
        // catalogue's, grown by the few names the checker's built-in scope adds: 6 % of
        // that run). A clone copies a few own names as cheaply, so they stay own.
        if self.own.names.len() <= FEW && Arc::strong_count(&self.base) > 1 {
            return self;
        }
        let mut table = Arc::unwrap_or_clone(self.base);
        for name in self.own.names {
            let sym = Symbol(table.names.len() as u32);
            table.names.push(name.clone());
            table.map.insert(name, sym);
        }
        Interner { base: Arc::new(table), own: Table::default(), scratch: String::new() }
    }

    fn lookup(&self, folded: &str) -> Option<Symbol> {
        self.base.map.get(folded).or_else(|| self.own.map.get(folded)).copied()
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

    #[test]
    fn get_folds_as_intern_does_short_long_and_latin1() {
        let mut interner = Interner::default();
        let long = "A".repeat(60) + "_Name";
        let names = ["ERR_DIVZERO", "Überlauf", long.as_str(), "x"];
        let syms: Vec<Symbol> = names.iter().map(|n| interner.intern(n)).collect();
        assert_eq!(interner.get("err_divzero"), Some(syms[0]));
        assert_eq!(interner.get("ÜBERLAUF"), Some(syms[1]));
        assert_eq!(interner.get(&long.to_lowercase()), Some(syms[2]));
        assert_eq!(interner.get("X"), Some(syms[3]));
        assert_eq!((interner.get("ERR_DIVZER"), interner.get("")), (None, None));
    }

    #[test]
    fn a_frozen_interner_keeps_its_symbols_and_its_clones_go_on_alone() {
        let mut interner = Interner::default();
        let (a, b) = (interner.intern("Alpha"), interner.intern("Beta"));
        let frozen = interner.freeze().freeze();
        let (mut one, mut two) = (frozen.clone(), frozen.clone());
        assert_eq!(one.intern("BETA"), b);
        assert_eq!(one.resolve(a), "alpha");
        // Both clones give the next symbol to their own new name, unseen by the other.
        let gamma = one.intern("Gamma");
        let delta = two.intern("Delta");
        assert_eq!((gamma.index(), delta.index()), (2, 2));
        assert_eq!((one.resolve(gamma), two.resolve(delta)), ("gamma", "delta"));
        assert_eq!((one.get("delta"), two.get("GAMMA")), (None, None));
        // Freezing a clone that grew keeps every symbol it gave.
        let refrozen = one.freeze();
        assert_eq!((refrozen.get("gamma"), refrozen.get("alpha")), (Some(gamma), Some(a)));
        assert_eq!(refrozen.resolve(gamma), "gamma");
    }

    #[test]
    fn freezing_onto_a_shared_prefix_keeps_every_symbol_few_or_many() {
        let mut interner = Interner::default();
        let alpha = interner.intern("Alpha");
        let shared = interner.freeze();
        for extra in [3, FEW + 8] {
            let mut grown = shared.clone();
            let syms: Vec<Symbol> = (0..extra).map(|i| grown.intern(&format!("Name{i}"))).collect();
            let frozen = grown.freeze();
            // Symbols go on from the prefix's one name, in the order interned.
            assert_eq!(syms.last().map(|s| s.index()), Some(extra));
            let mut copy = frozen.clone();
            assert_eq!(copy.intern("ALPHA"), alpha);
            assert_eq!(copy.get(&format!("NAME{}", extra - 1)), syms.last().copied());
            assert_eq!(copy.resolve(syms[0]), "name0");
            // The next name takes the next symbol.
            assert_eq!(copy.intern("Omega").index(), extra + 1);
        }
    }
}
