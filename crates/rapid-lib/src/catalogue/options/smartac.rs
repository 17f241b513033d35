//! Option: SmarTac: searching for work pieces by touch with the welding wire or
//! gas cup.
//!
//! Source: ABB, "Application manual - SmarTac" (RobotWare 6), chapter "RAPID
//! reference": Search_1D, Search_Groove and PDispAdd. Their full parameter lists are
//! not in any public text we could read: the calls' arguments are not checked (only
//! their names are resolved).

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    routine(
        "PROC Search_1D()",
        "SmarTac: a one-dimensional search that gives a displacement frame (arguments not checked).",
    )
    .unchecked_args(),
    routine("PROC Search_Groove()", "SmarTac: finds a groove's position and width (arguments not checked).")
        .unchecked_args(),
    routine("PROC PDispAdd()", "SmarTac: adds a search result to the program displacement (arguments not checked).")
        .unchecked_args(),
];
