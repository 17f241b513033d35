//! The built-in scope, prepared once: the catalogue's types, data and routines (with
//! their parameters) declared as the checker declares them, and the interner that
//! spells their names.
//!
//! Declaring the catalogue was the largest fixed cost of a check (every built-in
//! routine's parameters resolved again, for each check): now each thread declares it
//! once per set of present software options, and every check starts from a copy. The
//! copy shares what it can (the interner's names, the parameter lists) and copies the
//! rest. Per thread, not per process: the tables hold `Rc`s.
//!
//! The names the declaration interns beyond the catalogue's parse (named types such as
//! `signaldi`, the checker's well-known `switch`, `anytype`, `<ID>`) now come before
//! the names of the files checked; nothing a check reports depends on symbol order
//! (diagnostics are ordered by file and position).

use std::cell::RefCell;
use std::rc::Rc;

use rapid_lib::catalogue::options::{SoftwareOption, ALL_OPTIONS};
use rapid_syntax::{Interner, Symbol};
use rustc_hash::FxHashMap;

use crate::checker::{Checker, WellKnown};
use crate::diagnostic::SourceInput;
use crate::symbols::{DataInfo, Def, RoutineInfo};
use crate::types::{CoreTypes, TypeId, Types};

/// Different option sets kept per thread; one more replaces the oldest (a process
/// checks the tasks of one or two systems).
const KEPT: usize = 4;

/// The catalogue declared for one set of present options.
pub(crate) struct BuiltinScope {
    /// The catalogue's names and those the declaration interned, frozen: each check
    /// starts from a clone.
    pub(crate) interner: Interner,
    known: WellKnown,
    types: Types,
    core: CoreTypes,
    builtins: FxHashMap<Symbol, Def>,
    datas: Vec<DataInfo>,
    routines: Vec<RoutineInfo>,
    absent: FxHashMap<Symbol, &'static SoftwareOption>,
    opaque: FxHashMap<TypeId, &'static SoftwareOption>,
}

thread_local! {
    static SCOPES: RefCell<Vec<(Vec<bool>, Rc<BuiltinScope>)>> = const { RefCell::new(Vec::new()) };
}

/// The built-in scope of a system with `system_options` (`None`: every option).
pub(crate) fn builtin_scope(system_options: Option<&[String]>) -> Rc<BuiltinScope> {
    // The scope depends on the options only through which of the catalogue's are present.
    let key: Vec<bool> =
        ALL_OPTIONS.iter().map(|option| crate::options::has_option(system_options, Some(option))).collect();
    SCOPES.with(|scopes| {
        if let Some((_, scope)) = scopes.borrow().iter().find(|(k, _)| *k == key) {
            return Rc::clone(scope);
        }
        let scope = Rc::new(declare(system_options));
        let mut scopes = scopes.borrow_mut();
        if scopes.len() == KEPT {
            scopes.remove(0);
        }
        scopes.push((key, Rc::clone(&scope)));
        scope
    })
}

/// Declares the catalogue in an empty checker and keeps what it declared.
fn declare(system_options: Option<&[String]>) -> BuiltinScope {
    let (base, catalogue) = crate::catalogue();
    let mut interner = base.clone();
    let known = WellKnown {
        switch: interner.intern("switch"),
        anytype: interner.intern("anytype"),
        placeholder_id: interner.intern("<ID>"),
    };
    let mut ck = Checker::new(&[], known);
    ck.load_builtins(catalogue, system_options, &mut interner);
    BuiltinScope {
        interner: interner.freeze(),
        known,
        types: ck.types,
        core: ck.core,
        builtins: ck.scopes.builtins,
        datas: ck.datas,
        routines: ck.routines,
        absent: ck.unknowns.absent,
        opaque: ck.unknowns.opaque,
    }
}

impl<'a> Checker<'a> {
    /// A checker for `files` whose built-in scope is a copy of `scope`.
    pub(crate) fn with_builtins(files: &'a [SourceInput], scope: &BuiltinScope) -> Checker<'a> {
        let mut ck = Checker::new(files, scope.known);
        ck.types = scope.types.clone();
        ck.core = scope.core;
        ck.scopes.builtins = scope.builtins.clone();
        ck.datas = scope.datas.clone();
        ck.routines = scope.routines.clone();
        ck.unknowns.absent = scope.absent.clone();
        ck.unknowns.opaque = scope.opaque.clone();
        ck
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn codes(text: &str, options: &crate::Options) -> Vec<&'static str> {
        crate::check(&[SourceInput::from_text("T.mod", text)], options).iter().map(|d| d.code.as_str()).collect()
    }

    #[test]
    fn what_one_check_declares_does_not_reach_the_next() {
        // A configured signal is built-in data of the check that has it, only.
        let uses = "MODULE M\nPROC main()\n  SetDO doLamp, 1;\nENDPROC\nENDMODULE\n";
        let lamp = crate::PredefinedData { name: "doLamp".into(), type_name: "signaldo".into() };
        let configured = crate::Options { predefined: vec![lamp], ..Default::default() };
        assert_eq!(codes(uses, &configured), Vec::<&str>::new());
        assert_eq!(codes(uses, &crate::Options::default()), ["E0201"]);
        assert_eq!(codes(uses, &configured), Vec::<&str>::new());
    }

    #[test]
    fn a_check_without_an_option_and_one_with_it_alternate_in_one_thread() {
        // egmident and EGMGetId belong to EGM: E0217 on a system without it, fine with it.
        let uses = "MODULE M\nVAR egmident id;\nPROC main()\n  EGMGetId id;\nENDPROC\nENDMODULE\n";
        let without = crate::Options { system_options: Some(Vec::new()), ..Default::default() };
        let with = crate::Options { system_options: Some(vec!["EGM".into()]), ..Default::default() };
        for _ in 0..2 {
            assert_eq!(codes(uses, &without), ["E0217", "E0217"]);
            assert_eq!(codes(uses, &with), Vec::<&str>::new());
            assert_eq!(codes(uses, &crate::Options::default()), Vec::<&str>::new());
        }
    }

    #[test]
    fn each_option_set_has_its_own_scope_and_a_set_is_declared_once() {
        let none: Vec<String> = Vec::new();
        let all = builtin_scope(None);
        let without = builtin_scope(Some(&none));
        assert!(all.absent.is_empty());
        // A system without options lacks the names of every option the catalogue declares.
        assert!(!without.absent.is_empty());
        assert!(without.builtins.len() < all.builtins.len());
        assert!(Rc::ptr_eq(&all, &builtin_scope(None)));
        assert!(Rc::ptr_eq(&without, &builtin_scope(Some(&none))));
    }
}
