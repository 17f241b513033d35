//! Option: SmarTac: searching for work pieces by touch with the welding wire or
//! gas cup.
//!
//! Source: ABB, "Application manual - SmarTac" (RobotWare 6), chapter "RAPID
//! reference": Search_1D, Search_Groove and PDispAdd; the manual is not public to us.
//! The signatures are checked against public programs that call them: zwj12/ZhongXunRapid
//! `RAATCfg/RAPID/TASK1/PROGMOD/SmarTacTestModule.mod` (66 Search_1D, 14 Search_Groove,
//! 40 PDispAdd calls) and zwj12/AddInPackages `Ebara/Ebara RobotWare Add-in/RAPID/
//! T_ROB1/CalibDataModule.mod` (Search_1D with \Wire, \SearchStop and \WObj).
//!
//! The manual documents optional arguments no public program passes (search names,
//! limits…): the routines take optional arguments they do not declare
//! (`open_optionals`); every argument declared is checked.

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    // Verified: [\Wire] Result [\SearchStop] StartPoint SearchPoint Speed Tool [\WObj];
    // the result and the stop position are PERS data in public code.
    routine(
        r#"PROC Search_1D(\switch Wire, INOUT pose Result, \INOUT robtarget SearchStop, robtarget StartPoint, robtarget SearchPoint, speeddata Speed, PERS tooldata Tool, \PERS wobjdata WObj)"#,
        "SmarTac: a one-dimensional search that gives a displacement frame.",
    )
    .open_optionals(),
    // Verified: Result, the groove's width (a result), start and centre positions, the
    // search length (a number), speed and tool. uncertain: the names of the width and
    // length parameters (positional in every public call).
    routine(
        r#"PROC Search_Groove(INOUT pose Result, INOUT num GrooveWidth, robtarget StartPoint, robtarget CenterPoint, num SearchLength, speeddata Speed, PERS tooldata Tool, \PERS wobjdata WObj)"#,
        "SmarTac: finds a groove's position and width.",
    )
    .open_optionals(),
    // Verified: one pose, a search result.
    routine("PROC PDispAdd(pose DispFrame)", "SmarTac: adds a search result to the program displacement.")
        .open_optionals(),
];
