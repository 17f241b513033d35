//! Option: Force Control (661-2, Force Control for machining and assembly): moves
//! guided by a force/torque sensor.
//!
//! Source: ABB, "Application manual - Force Control" (RobotWare 6), chapter "RAPID
//! reference"; the manual is not public to us (its RobotWare 7 GoFa edition,
//! 3HAC083267-001, is quoted on public pages only by its table of contents). The
//! routines whose public callers we found are checked against them: FCLoadId is a
//! function returning the identified load (`TestLoad:=FCLoadId(\MaxMoveAx5:=30
//! \MaxMoveAx6:=70);`, `test_load := FCLoadId();`), FCCalib takes that load
//! (`FCCalib test_load;`), FCPress1LStart and FCPressL are called as
//! `FCPress1LStart p, v100 \Fy:=-2, 60 \UseSpdFFW \PosSupvDist:=60, z30, tool \WObj:=wobj0;`
//! and `FCPressL pEnd, vTravel, 50, fine, tool \WObj:=wobj1;`, FCGetForce is read as
//! `forces := FCGetForce();` (and with `\ContactForce`), FCAct as `FCAct tool \Load:=load`.
//! (Public RAPID programs found by a code search of GitHub; the calls above are
//! paraphrased, not copied.) The names of the data types and routines are also those the
//! rapid-for-vim syntax file lists for Force Control (KnoP-01/rapid-for-vim
//! `syntax/rapid.vim`). Routines no public program calls keep unchecked arguments.
//!
//! The checked routines take optional arguments they do not declare (`open_optionals`):
//! the manual documents more than public programs pass.

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    // Verified: public programs read xforce, yforce, zforce, xtorque, ytorque, ztorque.
    type_decl(
        "RECORD fcforcevector num xforce; num yforce; num zforce; num xtorque; num ytorque; num ztorque; ENDRECORD",
        "Force Control: a force (N) and a torque (Nm) along and about x, y, z.",
    ),
    opaque("fcframe", "Force Control: the reference frame of force control; values not public."),
    // uncertain: no public caller found; as we know the manual (no argument).
    routine("FUNC bool FCIsForceMode()", "Force Control: whether force control is active."),
    routine(r#"FUNC fcforcevector FCGetForce(\switch ContactForce)"#, "Force Control: the measured force and torque.")
        .open_optionals(),
    // Verified: a function returning loaddata, with \MaxMoveAx5 and \MaxMoveAx6 (degrees).
    routine(r#"FUNC loaddata FCLoadId(\num MaxMoveAx5, \num MaxMoveAx6)"#, "Force Control: identifies the tool's load.")
        .open_optionals(),
    // Verified: the load FCLoadId identified.
    routine("PROC FCCalib(loaddata Load)", "Force Control: calibrates the sensor with a load.").open_optionals(),
    // Verified: the tool first, \Load optional (a commented public call). uncertain: the
    // frame and damping arguments of the manual, accepted as undeclared optionals.
    routine(r#"PROC FCAct(PERS tooldata Tool, \loaddata Load)"#, "Force Control: activates force control with a tool.")
        .open_optionals(),
    routine("PROC FCDeact()", "Force Control: deactivates force control (arguments not checked).").unchecked_args(),
    routine("PROC FCRefStart()", "Force Control: starts a reference movement (arguments not checked).")
        .unchecked_args(),
    routine("PROC FCRefStop()", "Force Control: stops the reference movement (arguments not checked).")
        .unchecked_args(),
    // Verified: ToPoint, Speed, one of \Fx \Fy \Fz, the force threshold, \ForceChange,
    // \PosSupvDist, \UseSpdFFW, Zone, Tool, \WObj.
    routine(
        r#"PROC FCPress1LStart(robtarget ToPoint, speeddata Speed, \num Fx | num Fy | num Fz, num ForceThreshold, \num ForceChange, \num PosSupvDist, \switch UseSpdFFW, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj)"#,
        "Force Control: moves linearly until the press force is reached and starts pressing.",
    )
    .open_optionals(),
    // Verified: ToPoint, Speed, the force, Zone, Tool, \WObj.
    routine(
        r#"PROC FCPressL(robtarget ToPoint, speeddata Speed, num Force, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj)"#,
        "Force Control: a linear press movement.",
    )
    .open_optionals(),
    routine("PROC FCPressC()", "Force Control: a circular press movement (arguments not checked).").unchecked_args(),
    routine("PROC FCPressEnd()", "Force Control: ends a press movement (arguments not checked).").unchecked_args(),
    routine(
        "PROC FCCondWaitWhile()",
        "Force Control: waits while the force control conditions hold (arguments not checked).",
    )
    .unchecked_args(),
];
