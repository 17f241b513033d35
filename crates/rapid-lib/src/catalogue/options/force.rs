//! Option: Force Control (661-2, Force Control for machining and assembly): moves
//! guided by a force/torque sensor.
//!
//! Source: ABB, "Application manual - Force Control" (RobotWare 6), chapter "RAPID
//! reference". fcforcevector and FCIsForceMode are as the manual gives them; the
//! other instructions take many optional arguments we could not read in full in a
//! public text: their arguments are not checked (only their names are resolved).

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    type_decl(
        "RECORD fcforcevector num xforce; num yforce; num zforce; num xtorque; num ytorque; num ztorque; ENDRECORD",
        "Force Control: a force (N) and a torque (Nm) along and about x, y, z.",
    ),
    opaque("fcframe", "Force Control: the reference frame of force control; values not public."),
    routine("FUNC bool FCIsForceMode()", "Force Control: whether force control is active."),
    routine("FUNC fcforcevector FCGetForce()", "Force Control: the measured force and torque (arguments not checked).")
        .unchecked_args(),
    routine("PROC FCAct()", "Force Control: activates force control with a tool (arguments not checked).")
        .unchecked_args(),
    routine("PROC FCDeact()", "Force Control: deactivates force control (arguments not checked).").unchecked_args(),
    routine("PROC FCCalib()", "Force Control: calibrates the sensor with a load (arguments not checked).")
        .unchecked_args(),
    routine("PROC FCLoadId()", "Force Control: identifies the tool's load (arguments not checked).").unchecked_args(),
    routine("PROC FCRefStart()", "Force Control: starts a reference movement (arguments not checked).")
        .unchecked_args(),
    routine("PROC FCRefStop()", "Force Control: stops the reference movement (arguments not checked).")
        .unchecked_args(),
    routine("PROC FCPress1LStart()", "Force Control: starts a linear press movement (arguments not checked).")
        .unchecked_args(),
    routine("PROC FCPressL()", "Force Control: a linear press movement (arguments not checked).").unchecked_args(),
    routine("PROC FCPressC()", "Force Control: a circular press movement (arguments not checked).").unchecked_args(),
    routine("PROC FCPressEnd()", "Force Control: ends a press movement (arguments not checked).").unchecked_args(),
    routine(
        "PROC FCCondWaitWhile()",
        "Force Control: waits while the force control conditions hold (arguments not checked).",
    )
    .unchecked_args(),
];
