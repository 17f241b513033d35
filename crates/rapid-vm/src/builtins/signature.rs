//! Where a built-in's arguments are, read from its declaration in the catalogue.
//!
//! A built-in gets its arguments in parameter order (`BuiltinFn`). Rather than copy
//! positions by hand (`to: 1, speed: 3, …`), a family asks the declared signature for
//! the position of a parameter by name, once: the layout is built the first time it is
//! used (a `LazyLock` beside the built-in) and every call reads plain indices.
//!
//! The catalogue is parsed once per process for this; positions count every declared
//! parameter, alternatives (`\num V | num T`) one each, exactly as the checker numbers
//! them for the compiler.

use std::sync::LazyLock;

use rapid_lib::catalogue::EntryKind;
use rapid_syntax::ast::Item;
use rustc_hash::FxHashMap;

/// A parameter the signature does not have: `args.get(ABSENT)` is `None`.
pub const ABSENT: usize = usize::MAX;

/// Every catalogue routine's parameter names, by lower-case routine name.
static PARAMS: LazyLock<FxHashMap<String, Vec<String>>> = LazyLock::new(|| {
    let mut interner = rapid_syntax::Interner::default();
    let cat = rapid_lib::load(&mut interner);
    let mut out = FxHashMap::default();
    for loaded in &cat.entries {
        if loaded.entry.kind != EntryKind::Routine {
            continue;
        }
        let Some(Item::Routine(routine)) = cat.item(loaded) else { continue };
        let names = routine
            .params
            .iter()
            .filter(|p| p.placeholder.is_none())
            .map(|p| p.name.span.text(&cat.text).to_string())
            .collect();
        out.insert(routine.name.span.text(&cat.text).to_ascii_lowercase(), names);
    }
    out
});

/// The declared parameters of one built-in.
#[derive(Debug, Clone, Copy)]
pub struct Signature {
    params: &'static [String],
}

/// The signature of the catalogue routine `routine` (any letter case); empty when the
/// catalogue has no such routine (a test of each layout catches a misspelt name).
pub fn of(routine: &str) -> Signature {
    let params: &'static FxHashMap<String, Vec<String>> = &PARAMS;
    Signature { params: params.get(&routine.to_ascii_lowercase()).map_or(&[], Vec::as_slice) }
}

impl Signature {
    /// The position of parameter `name` (any letter case), or [`ABSENT`].
    pub fn at(&self, name: &str) -> usize {
        self.params.iter().position(|p| p.eq_ignore_ascii_case(name)).unwrap_or(ABSENT)
    }

    /// The position of parameter `name`, if the signature has it.
    pub fn opt(&self, name: &str) -> Option<usize> {
        Some(self.at(name)).filter(|&at| at != ABSENT)
    }

    /// The position of the first of `names` the signature has, or [`ABSENT`].
    pub fn first_of(&self, names: &[&str]) -> usize {
        names.iter().map(|n| self.at(n)).find(|&at| at != ABSENT).unwrap_or(ABSENT)
    }

    /// How many parameters are declared.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.params.len()
    }
}

/// Declares where one built-in's arguments are, by parameter name: a struct of
/// positions and a `LazyLock` static that reads them from the declaration the first
/// time it is used, with a test that every name is declared (and that the built-ins
/// after `|`, which share the implementation, have them at the same places).
///
/// ```ignore
/// layout! {
///     /// `ITimer [\Single] | [\SingleSafe] Time Interrupt`.
///     static ITIMER: TimerArgs = "ITimer" {
///         single: "Single", single_safe: "SingleSafe", time: "Time", interrupt: "Interrupt",
///     }
/// }
/// ```
#[macro_export]
macro_rules! layout {
    ($(
        $(#[$doc:meta])*
        static $static:ident: $ty:ident = $routine:literal $(| $also:literal)* {
            $($field:ident: $param:literal),* $(,)?
        }
    )*) => {$(
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        struct $ty {
            $($field: usize),*
        }

        impl $ty {
            fn of(routine: &str) -> $ty {
                let sig = $crate::ext::signature(routine);
                $ty { $($field: sig.at($param)),* }
            }
        }

        static $static: std::sync::LazyLock<$ty> = std::sync::LazyLock::new(|| $ty::of($routine));

        #[cfg(test)]
        #[allow(non_snake_case)]
        mod $static {
            #[test]
            fn every_parameter_is_declared() {
                let sig = $crate::ext::signature($routine);
                for name in [$($param),*] {
                    assert!(sig.opt(name).is_some(), "{} declares no parameter {name}", $routine);
                }
                $(assert_eq!(super::$ty::of($also), *super::$static, "{} and {}", $routine, $also);)*
            }
        }
    )*};
}
pub use crate::layout;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_count_every_parameter_and_alternative() {
        // PROC MoveJ(\switch Conc, robtarget ToPoint, \identno ID, speeddata Speed,
        //            \num V | num T, zonedata Zone, \num Z, \stoppointdata Inpos,
        //            PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)
        let sig = of("movej");
        assert_eq!(sig.len(), 12);
        assert_eq!((sig.at("Conc"), sig.at("ToPoint"), sig.at("speed")), (0, 1, 3));
        assert_eq!((sig.at("V"), sig.at("T"), sig.at("Zone")), (4, 5, 6));
        assert_eq!(sig.at("CirPoint"), ABSENT);
        assert_eq!(sig.first_of(&["ToPoint", "ToJointPos"]), 1);
        assert_eq!(of("MoveAbsJ").first_of(&["ToPoint", "ToJointPos"]), 1);
        assert_eq!(of("NoSuchRoutine").len(), 0);
    }
}
