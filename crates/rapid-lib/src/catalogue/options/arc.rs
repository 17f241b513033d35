//! Option: Arc (RobotWare Arc, option 633 of RobotWare 6): arc welding process
//! instructions and their data.
//!
//! Source: ABB, "Application manual - Arc and Arc Sensor" (RobotWare 6), chapter
//! "RAPID reference": data types welddata, seamdata, weavedata, arcdata, trackdata and
//! the instructions ArcL, ArcC, ArcLStart, ArcLEnd, ArcCStart, ArcCEnd. The component
//! lists of welddata, seamdata, weavedata and arcdata are the manual's; the arc welding
//! data RobotStudio writes for RobotWare 6 has exactly these shapes (welddata 4,
//! arcdata 9, seamdata 16, weavedata 15 components).

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
    // uncertain: the optional arguments beyond \ID, \Weave, \Inpos, \WObj, \TLoad, \Track
    // and \SeamName (process-specific ones of later RobotWare versions) are not declared.
    routine(
        r#"PROC ArcLStart(robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Moves linearly to ToPoint and starts the arc welding process there.",
    ),
    routine(
        r#"PROC ArcL(robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds linearly to ToPoint.",
    ),
    routine(
        r#"PROC ArcLEnd(robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds linearly to ToPoint and ends the process there.",
    ),
    routine(
        r#"PROC ArcCStart(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Moves circularly to ToPoint and starts the arc welding process there.",
    ),
    routine(
        r#"PROC ArcC(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds circularly through CirPoint to ToPoint.",
    ),
    routine(
        r#"PROC ArcCEnd(robtarget CirPoint, robtarget ToPoint, \identno ID, speeddata Speed, seamdata Seam, welddata Weld, \weavedata Weave, zonedata Zone, \stoppointdata Inpos, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \trackdata Track, \string SeamName)"#,
        "Welds circularly to ToPoint and ends the process there.",
    ),
];
