//! Names of ABB software options that OpenRAPID does not provide: a program written for a
//! controller with one of them names instructions and data types the catalogue lacks.
//! `rapid check` still reports them as undefined, and says which option they belong to,
//! so the user knows the program is not wrong but needs what we do not simulate.

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
