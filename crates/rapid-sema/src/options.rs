//! Software options and unreadable code in name resolution.
//!
//! - The catalogue declares the options real systems use most (`rapid_lib::catalogue::
//!   options`). On a system that lacks one (its backup or manifest names its options),
//!   the option's names are not declared: a use is E0217 "belongs to option X, which
//!   this system does not have", never "undefined". Without system information every
//!   option is assumed present: a user checking a loose module cannot say what the
//!   target controller has installed.
//! - Names of options the catalogue does not declare are still reported as undefined,
//!   with a note naming the option (`note_for`), so the user knows the program is not
//!   wrong but needs what we do not provide.
//! - In a task that loads an encrypted module, a name defined nowhere readable may be
//!   defined in that module: W0218, a warning naming the module, instead of the error.

use rapid_lib::catalogue::options::{self as catalogue_options, SoftwareOption};
use rapid_lib::{LoadedCatalogue, LoadedEntry};
use rapid_syntax::ast::Item;
use rapid_syntax::{Interner, Span, Symbol};
use rustc_hash::FxHashMap;

use crate::checker::Checker;
use crate::codes::Code;
use crate::types::TypeId;

/// What name resolution must know about names it cannot see.
#[derive(Debug, Default)]
pub(crate) struct Unknowns {
    /// Names of the catalogue's options the system lacks, with their option.
    pub(crate) absent: FxHashMap<Symbol, &'static SoftwareOption>,
    /// Option types whose components are not public.
    pub(crate) opaque: FxHashMap<TypeId, &'static SoftwareOption>,
    /// The display paths of the task's encrypted modules.
    pub(crate) encrypted: Vec<String>,
}

impl Unknowns {
    /// Remembers the name an entry of an absent option would declare.
    pub(crate) fn note_absent(&mut self, cat: &LoadedCatalogue, entry: &LoadedEntry, interner: &mut Interner) {
        let Some(option) = entry.option else { return };
        let sym = match cat.item(entry) {
            Some(Item::Type(def)) => def.name().sym,
            Some(Item::Data(decl)) => decl.name.sym,
            Some(Item::Routine(routine)) => routine.name.sym,
            Some(Item::Placeholder(..)) => return,
            None => interner.intern(entry.entry.text.split_whitespace().next().unwrap_or("")),
        };
        self.absent.insert(sym, option);
    }
}

/// Whether a system with `system_options` (`None`: unknown) has `option` (`None`:
/// RobotWare itself, always present).
pub(crate) fn has_option(system_options: Option<&[String]>, option: Option<&'static SoftwareOption>) -> bool {
    match (system_options, option) {
        (_, None) | (None, _) => true,
        (Some(names), Some(option)) => {
            names.iter().any(|name| catalogue_options::find(name).is_some_and(|found| found.short == option.short))
        }
    }
}

impl Checker<'_> {
    /// Reports a name defined nowhere in the task: E0217 for a name of an option the
    /// system lacks, W0218 in a task with an encrypted module, else `code` with
    /// `message`.
    pub(crate) fn undefined(&mut self, code: Code, span: Span, sym: Symbol, message: String) {
        let text = self.text(span).split('(').next().unwrap_or("").trim().to_string();
        if let Some(option) = self.unknowns.absent.get(&sym) {
            let message = format!("`{text}` belongs to option {}, which this system does not have", option.name);
            return self.diag(Code::OptionMissing, span, message);
        }
        if !self.unknowns.encrypted.is_empty() {
            let modules = self.unknowns.encrypted.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(", ");
            let message =
                format!("{message}; it may be defined in the encrypted module {modules}, which cannot be read");
            return self.diag(Code::UndefinedBesideEncrypted, span, message);
        }
        self.diag(code, span, message)
    }
}

/// The option whose instruction, function or data type `name` is, when it is one of the
/// names we know of (compared without case).
pub(crate) fn option_of(name: &str) -> Option<&'static str> {
    let lower = name.to_ascii_lowercase();
    // EGM's instructions are spelt `EGM` + a capitalised word (EGMActJoint, EGMRunPose);
    // its data types are lower case. A user's own `egm_setup` is none of them.
    let egm_instruction =
        name.strip_prefix("EGM").is_some_and(|rest| rest.starts_with(|c: char| c.is_ascii_uppercase()));
    if egm_instruction || EGM_TYPES.contains(&lower.as_str()) {
        return Some("Externally Guided Motion (EGM)");
    }
    OPTION_NAMES.iter().find(|(names, _)| names.contains(&lower.as_str())).map(|&(_, option)| option)
}

/// The clause a diagnostic about `name` ends with, empty for a name of no known option.
pub(crate) fn note_for(name: &str) -> String {
    match option_of(name) {
        Some(option) => format!(" (`{name}` belongs to ABB's {option} option, which OpenRAPID does not provide)"),
        None => String::new(),
    }
}

/// EGM's data types (lower case).
// uncertain: as we remember RobotWare 6's EGM manual.
const EGM_TYPES: &[&str] = &["egmident", "egmstate", "egmstopmode", "egmframetype", "egm_minmax"];

/// Names (lower case) by option, beyond the EGM rule.
const OPTION_NAMES: &[(&[&str], &str)] = &[
    (
        &[
            "arcl",
            "arcc",
            "arclstart",
            "arclend",
            "arccstart",
            "arccend",
            "arcl1",
            "arcl2",
            "arcc1",
            "arcc2",
            "arcrefresh",
            "seamdata",
            "welddata",
            "weavedata",
            "arcdata",
            "trackdata",
        ],
        "Arc welding (RobotWare Arc)",
    ),
    (&["spotl", "spotj", "spotml", "spotmj", "spotdata", "gundata", "forcedata"], "Spot welding"),
    // The names KnoP-01/rapid-for-vim `syntax/rapid.vim` lists for these options; public
    // arc welding backups (taeyangshim-stack/s25016, zwj12/ZhongXunRapid) use them.
    (
        &[
            "arcrepl",
            "arcadaptlstart",
            "arcadaptl",
            "arcadaptc",
            "arcadaptlend",
            "arcadaptcend",
            "arcadaptrepl",
            "arccalclstart",
            "arccalcl",
            "arccalcc",
            "arccalclend",
            "arccalccend",
            "mpsavepath",
            "mploadpath",
            "mpreadinpath",
            "mpoffseaxonpath",
            "multidata",
            "adaptdata",
        ],
        "WeldGuide and MultiPass",
    ),
    (
        &["capl", "capc", "capdata", "captrackdata", "capweavedata", "capspeeddata", "weavestartdata", "caprefresh"],
        "Continuous Application Platform",
    ),
    (
        &["daactproc", "dadeactproc", "dadefextsig", "dadefprocsig", "dadefprocdata", "dagetcurrdata", "dasetcurrdata"],
        "Discrete Application Platform",
    ),
    (
        &[
            "fcact",
            "fcdeact",
            "fccalib",
            "fcloadid",
            "fcpress1lstart",
            "fcpressl",
            "fcpressc",
            "fcpressend",
            "fcrefstart",
            "fcrefstop",
            "fcgetforce",
            "fcisforcemode",
            "fccondwaitwhile",
            "fcsupvforce",
            "fcforcevector",
            "fccondstatus",
            "fcframe",
        ],
        "Force Control",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn option_names_are_recognised_without_case() {
        assert_eq!(option_of("EGMActJoint"), Some("Externally Guided Motion (EGM)"));
        assert_eq!(option_of("egmident"), Some("Externally Guided Motion (EGM)"));
        assert_eq!(option_of("ArcLStart"), Some("Arc welding (RobotWare Arc)"));
        assert_eq!(option_of("FCAct"), Some("Force Control"));
        assert_eq!(option_of("ArcRepL"), Some("WeldGuide and MultiPass"));
        assert_eq!(option_of("multidata"), Some("WeldGuide and MultiPass"));
        assert_eq!(option_of("DaGetCurrData"), Some("Discrete Application Platform"));
        assert_eq!(option_of("MoveL"), None);
        assert_eq!(option_of("my_proc"), None);
        // A user's own routine that happens to start with `egm` is no EGM name.
        assert_eq!(option_of("egm_setup"), None);
        assert_eq!(option_of("egmCheckRange"), None);
    }

    #[test]
    fn the_note_names_the_option() {
        assert_eq!(
            note_for("welddata"),
            " (`welddata` belongs to ABB's Arc welding (RobotWare Arc) option, which OpenRAPID does not provide)"
        );
        assert_eq!(note_for("pick"), "");
    }
}
