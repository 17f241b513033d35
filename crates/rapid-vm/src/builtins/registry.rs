//! The registry of built-in implementations. Each family file registers its built-ins
//! in one table beside their code (`pub(super) static FAMILY: Family`), under the name
//! the catalogue declares them by (`crates/rapid-lib/src/catalogue/`); `FAMILIES` in
//! `builtins/mod.rs` lists the families. What the compiler must know about how a
//! built-in takes its arguments is in its catalogue entry (`RoutineFlags`); what
//! `rapid run` does with it is here: the Rust function a call runs, its pure form for
//! the fast loop, or the instructions the compiler makes of it.
//!
//! The registry is built once, on first use: the families' tables are concatenated (a
//! built-in's id is its position) and indexed by lower-case name, so a call site finds
//! its built-in once, when it is compiled; running a call indexes by id.
//!
//! A catalogue routine that is in no family is listed in `not_yet.rs` with the reason;
//! a program calling it is refused at load ("not supported by `rapid run` yet"). The
//! tests below hold the three in step. Routines of software options (catalogue
//! `options/`) are in no family: a call is refused at load naming the option.

use rustc_hash::FxHashMap;

use super::pure::PureFn;
use super::{BuiltinFn, BuiltinId, Ctx};
use crate::error::RapidError;
use crate::value::Value;

/// One family's registrations, with the file that implements them (for the docs).
pub struct Family {
    pub file: &'static str,
    pub builtins: &'static [Builtin],
}

/// How `rapid run` runs one built-in.
#[derive(Clone, Copy)]
pub struct Builtin {
    /// The name as the catalogue spells it.
    pub name: &'static str,
    /// What a call runs (arguments in parameter order, see [`BuiltinFn`]).
    pub run: BuiltinFn,
    /// A pure form the fast loop may call on the arguments where they lie (`pure.rs`).
    pub pure: Option<PureFn>,
    /// The compiler's own form of the call (`compile/call.rs`), in place of `run` or
    /// (Break outside a loop, ArgName) beside it.
    pub compiled: Option<Compiled>,
}

/// Built-ins the compiler turns into instructions of its own.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Compiled {
    /// `Present(p)`: whether an optional parameter of the routine was passed.
    Present,
    /// `CallByVar Name, Number`: a late-bound call.
    CallByVar,
    /// `Type(Data)`: the data's type name, known when compiling.
    Type,
    /// `WaitUntil`: a loop that evaluates the condition at every poll.
    WaitUntil,
    /// `Continue`: a jump to the next pass of the innermost loop.
    Continue,
    /// `Break`: inside a loop a jump out of it; outside one, a call of `run`.
    Break,
    /// `ArgName`: a call of `run` whose first argument is not evaluated; the call site
    /// records the data object it names.
    ArgName,
}

/// A built-in that runs as the Rust function `run`.
pub const fn native(name: &'static str, run: BuiltinFn) -> Builtin {
    Builtin { name, run, pure: None, compiled: None }
}

/// A built-in the compiler always turns into instructions of its own.
pub const fn compiled(name: &'static str, how: Compiled) -> Builtin {
    Builtin { name, run: compiled_only, pure: None, compiled: Some(how) }
}

impl Builtin {
    /// With a pure form for the fast loop; it must give what `run` gives whenever it
    /// answers (see `pure.rs`).
    pub const fn with_pure(self, pure: PureFn) -> Builtin {
        Builtin { pure: Some(pure), ..self }
    }

    /// With a form of its own in the compiler, `run` serving where that form says.
    pub const fn compiled_as(self, how: Compiled) -> Builtin {
        Builtin { compiled: Some(how), ..self }
    }
}

/// `run` of a built-in that is always compiled into instructions: never called.
fn compiled_only(_: &mut Ctx<'_>, _: &[Value]) -> Result<Option<Value>, RapidError> {
    Err(RapidError::fatal("internal error: a built-in compiled into instructions was called"))
}

/// Every family's built-ins, and an index by lower-case name.
pub(super) struct Registry {
    pub(super) builtins: Vec<Builtin>,
    by_name: FxHashMap<String, BuiltinId>,
    /// The family of each built-in (an index into `FAMILIES`), for the docs.
    families: Vec<u16>,
}

impl Registry {
    pub(super) fn build(families: &[&Family]) -> Registry {
        let mut builtins = Vec::new();
        let mut of_family = Vec::new();
        let mut by_name = FxHashMap::default();
        for (family_idx, family) in families.iter().enumerate() {
            for builtin in family.builtins {
                let id = BuiltinId(builtins.len() as u16);
                // The first registration of a name wins; a test refuses a second.
                by_name.entry(builtin.name.to_ascii_lowercase()).or_insert(id);
                builtins.push(*builtin);
                of_family.push(family_idx as u16);
            }
        }
        Registry { builtins, by_name, families: of_family }
    }

    pub(super) fn lookup(&self, name: &str) -> Option<BuiltinId> {
        self.by_name.get(name.to_ascii_lowercase().as_str()).copied()
    }

    pub(super) fn family_of(&self, id: BuiltinId) -> usize {
        self.families[id.0 as usize] as usize
    }
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use rapid_lib::catalogue::EntryKind;
    use rapid_syntax::ast::Item;

    use super::super::{lookup, not_yet, registered, FAMILIES};

    /// Every routine the catalogue declares, except those of software options (none
    /// runs: a call is refused at load with the option's name): lower-case name →
    /// name as spelled.
    fn catalogue_routines() -> BTreeMap<String, String> {
        let mut interner = rapid_syntax::Interner::default();
        let cat = rapid_lib::load(&mut interner);
        let mut out = BTreeMap::new();
        for loaded in &cat.entries {
            if loaded.entry.kind != EntryKind::Routine || loaded.option.is_some() {
                continue;
            }
            if let Some(Item::Routine(routine)) = cat.item(loaded) {
                let name = routine.name.span.text(&cat.text).to_string();
                out.insert(name.to_ascii_lowercase(), name);
            }
        }
        out
    }

    #[test]
    fn every_catalogue_routine_is_registered_or_refused_with_a_reason() {
        let routines = catalogue_routines();
        let mut missing = Vec::new();
        for name in routines.values() {
            let runs = lookup(name).is_some();
            let refused = not_yet::reason(name);
            match (runs, refused) {
                (true, Some(_)) => missing.push(format!("{name}: registered and listed in not_yet.rs")),
                (false, None) => missing.push(format!("{name}: neither registered nor listed in not_yet.rs")),
                (false, Some(reason)) if reason.trim().is_empty() => {
                    missing.push(format!("{name}: listed in not_yet.rs without a reason"))
                }
                _ => {}
            }
        }
        for &(name, _) in not_yet::NOT_YET {
            if !routines.contains_key(&name.to_ascii_lowercase()) {
                missing.push(format!("{name}: in not_yet.rs but not in the catalogue"));
            }
        }
        assert!(missing.is_empty(), "built-ins out of step:\n{}", missing.join("\n"));
    }

    #[test]
    fn every_registration_is_a_catalogue_routine_registered_once() {
        let routines = catalogue_routines();
        let mut seen = BTreeMap::new();
        let mut wrong = Vec::new();
        for family in FAMILIES {
            for builtin in family.builtins {
                let key = builtin.name.to_ascii_lowercase();
                match routines.get(&key) {
                    None => wrong.push(format!("{} ({}): no catalogue entry", builtin.name, family.file)),
                    Some(spelled) if spelled != builtin.name => {
                        wrong.push(format!("{} ({}): the catalogue spells it {spelled}", builtin.name, family.file))
                    }
                    Some(_) => {}
                }
                if let Some(first) = seen.insert(key, family.file) {
                    wrong.push(format!("{} registered twice ({first}, {})", builtin.name, family.file));
                }
            }
        }
        assert!(wrong.is_empty(), "registrations out of step:\n{}", wrong.join("\n"));
        assert_eq!(registered().count(), seen.len());
    }
}
