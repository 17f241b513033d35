//! Option: Arc (RobotWare Arc, option 633 of RobotWare 6): arc welding process
//! instructions and their data.
//!
//! Source: ABB, "Application manual - Arc and Arc Sensor" (RobotWare 6), chapter
//! "RAPID reference": data types welddata, seamdata, weavedata, arcdata, trackdata and
//! the instructions ArcL, ArcC, ArcLStart, ArcLEnd, ArcCStart, ArcCEnd; the manual is
//! not public to us. The component lists of welddata, seamdata, weavedata and arcdata
//! are as we know the manual; the shapes are verified against public arc welding data
//! (welddata 4 components with two arcdata of 9, seamdata 16, weavedata 15; e.g.
//! ravenorb/abb-robot-welder `RAPID/PROGMOD/ProgSide1.mod`, zwj12/ZhongXunRapid
//! `RAATCfg/RAPID/TASK1/PROGMOD/WeldTestModule.mod`, taeyangshim-stack/s25016's
//! gantry backups). uncertain: the component names (no public text gives them).
//!
//! The instructions are checked against about 1,700 public calls (the three sources
//! above and zwj12/AddInPackages): ToPoint (CirPoint first for the circular ones),
//! \ID, Speed, Seam, Weld, \Weave, Zone, Tool, \WObj, \Track, \SeamName, in this order.
//! Arc's manual documents more optional arguments, and other options add some (Optical
//! tracking's \PreProcessTracking in zwj12/AddInPackages `Intelligent Laser/
//! ILOpticalTracking RobotWare Add-in/RAPID/OpticalTrackingModule.mod`): the
//! instructions take optional arguments they do not declare (`open_optionals`).

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    // ---- Data types ---------------------------------------------------------------------
    // uncertain: the manual says the power source's configuration decides which
    // arcdata components are shown and used; all nine exist in the data.
    type_decl(
        "RECORD arcdata num sched; num mode; num voltage; num wirefeed; num control; num current; num voltage2; num wirefeed2; num control2; ENDRECORD",
        "Arc data: the welding equipment's settings (schedule, mode, voltage, wire feed, current…).",
    ),
    type_decl(
        "RECORD welddata num weld_speed; num org_weld_speed; arcdata main_arc; arcdata org_arc; ENDRECORD",
        "Weld data: the weld speed and the arc settings of the weld phase.",
    ),
    type_decl(
        "RECORD seamdata num purge_time; num preflow_time; arcdata ign_arc; num ign_move_delay; num scrape_start; num heat_speed; num heat_time; num heat_distance; arcdata heat_arc; num cool_time; num fill_time; arcdata fill_arc; num bback_time; num rback_time; arcdata bback_arc; num postflow_time; ENDRECORD",
        "Seam data: the start (ignition, heat) and end (crater fill, burnback) phases of a seam.",
    ),
    type_decl(
        "RECORD weavedata num weave_shape; num weave_type; num weave_length; num weave_width; num weave_height; num dwell_left; num dwell_center; num dwell_right; num weave_dir; num weave_tilt; num weave_ori; num weave_bias; num org_weave_width; num org_weave_height; num org_weave_bias; ENDRECORD",
        "Weave data: the shape, size and dwells of the weaving pattern.",
    ),
    // The components of trackdata depend on the seam tracking sensor installed
    // (WeldGuide, optical trackers): no one public list covers them.
    opaque("trackdata", "Seam tracking data for a tracking sensor (components not public: accepted opaquely)."),
    // ---- Instructions -------------------------------------------------------------------
    // Verified as the module doc says; \Inpos and \TLoad are as we know the manual (no
    // public call passes them).
    routine(
        r#"PROC ArcLStart(robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Moves linearly to ToPoint and starts the arc welding process there.",
    )
    .open_optionals(),
    routine(
        r#"PROC ArcL(robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds linearly to ToPoint.",
    )
    .open_optionals(),
    routine(
        r#"PROC ArcLEnd(robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds linearly to ToPoint and ends the process there.",
    )
    .open_optionals(),
    routine(
        r#"PROC ArcCStart(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Moves circularly to ToPoint and starts the arc welding process there.",
    )
    .open_optionals(),
    routine(
        r#"PROC ArcC(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds circularly through CirPoint to ToPoint.",
    )
    .open_optionals(),
    routine(
        r#"PROC ArcCEnd(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds circularly to ToPoint and ends the process there.",
    )
    .open_optionals(),
    // Verified (taeyangshim-stack/s25016 `PlanB_Moving_WObj_2026-03-05/RAPID/TASK7/PROGMOD/
    // Gantry_MainModule.mod`, zwj12/AddInPackages Ebara `SharedModule.mod`): a joint
    // position, \ID, speed, zone and \Start; listed among Arc's instructions by
    // KnoP-01/rapid-for-vim.
    routine(
        r#"PROC ArcMoveExtJ(jointtarget ToJointPos, \identno ID, speeddata Speed, zonedata Zone, \switch Start)"#,
        "Moves external axes only, within an arc welding sequence.",
    )
    .open_optionals(),
    // Public programs call it bare or with \WeldSpeed and \WeaveWidth (zwj12/AddInPackages
    // Ebara `WeldTestModule.mod`). uncertain: its other optional arguments.
    routine(
        r#"PROC ArcRefresh(\num WeldSpeed, \num WeaveWidth)"#,
        "Applies changed weld and weave data to the weld in progress.",
    )
    .open_optionals(),
];
