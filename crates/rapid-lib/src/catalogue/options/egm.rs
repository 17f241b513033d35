//! Option: Externally Guided Motion (EGM), option 689-1 of RobotWare 6.
//!
//! Source: ABB, "Application manual - Externally Guided Motion", document
//! 3HAC073318-001 (the number public EGM projects cite, e.g. abb_motion_program_exec's
//! `docs/egm.md`), chapter "RAPID reference"; the manual itself is not public to us.
//! Each routine is checked against public programs that call it (the sources are named
//! per entry; "ABB's state machine add-in" is `TRobEGM.mod` of ABB's RobotWare
//! StateMachine Add-In, BSD-licensed, as shipped in
//! panin-anan/abb_SAMXL_Grinding_RAPID `HOME/Projects/BrightSkyGrinder/Loop_grind/`;
//! "motion-program-exec" is rpiRobotics/abb_motion_program_exec
//! `robot/HOME/motion_program_exec_egm.mod`). The names of the data types, constants and
//! instructions are also those the vim-rapid syntax file lists for EGM
//! (KnoP-01/rapid-for-vim `syntax/rapid.vim`).
//!
//! The manual may document optional arguments no public program passes (later
//! RobotWare versions add some): the routines take optional arguments they do not
//! declare (`open_optionals`); every argument declared is checked.

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    // ---- Data types ---------------------------------------------------------------------
    non_value("egmident", "Identifies one EGM process (one mechanical unit's external guidance)."),
    type_decl("ALIAS num egmstate;", "The state of an EGM process (EGM_STATE_DISCONNECTED, _CONNECTED, _RUNNING)."),
    type_decl("ALIAS num egmstopmode;", "How an EGM movement stops: EGM_STOP_HOLD or EGM_STOP_RAMP_DOWN."),
    type_decl("ALIAS num egmframetype;", "Which frame EGM corrections and sensor values are given in."),
    type_decl("RECORD egm_minmax num min; num max; ENDRECORD", "A convergence range: EGM is done when the deviation stays between min and max."),
    // ---- Constants ------------------------------------------------------------------------
    // Verified: every name is used by public programs (ABB's state machine add-in
    // compares EGMGetState with the three states; motion-program-exec assigns each
    // frame type; EGM_STOP_HOLD and EGM_STOP_RAMP_DOWN are passed to EGMRun*/EGMStop).
    // uncertain: the numeric values. No public text gives them (programs only use the
    // names); they are as we remember the manual's tables. A program that compares an
    // EGM constant with a literal number depends on them.
    data("CONST egmstate EGM_STATE_DISCONNECTED := 0;", "EGM state: the process is not set up."),
    data("CONST egmstate EGM_STATE_CONNECTED := 1;", "EGM state: set up, not moving."),
    data("CONST egmstate EGM_STATE_RUNNING := 2;", "EGM state: the robot is moved by EGM."),
    data("CONST egmstopmode EGM_STOP_HOLD := 0;", "EGM stop mode: stop where the robot is."),
    data("CONST egmstopmode EGM_STOP_RAMP_DOWN := 1;", "EGM stop mode: ramp the correction down before stopping."),
    data("CONST egmframetype EGM_FRAME_BASE := 0;", "EGM frame: the robot base frame."),
    data("CONST egmframetype EGM_FRAME_TOOL := 1;", "EGM frame: the tool frame."),
    data("CONST egmframetype EGM_FRAME_WOBJ := 2;", "EGM frame: the work object frame."),
    data("CONST egmframetype EGM_FRAME_WORLD := 3;", "EGM frame: the world frame."),
    data("CONST egmframetype EGM_FRAME_JOINT := 4;", "EGM frame: joint values."),
    // ---- Identity and state ---------------------------------------------------------------
    // Verified (ABB's state machine add-in, motion-program-exec): one egmident.
    routine("PROC EGMGetId(VAR egmident EGMid)", "Reserves an EGM process identity.")
        .open_optionals(),
    routine("FUNC egmstate EGMGetState(VAR egmident EGMid)", "Returns the state of an EGM process.")
        .open_optionals(),
    routine("PROC EGMReset(VAR egmident EGMid)", "Releases an EGM process identity and resets its process.")
        .open_optionals(),
    // ---- Setup ---------------------------------------------------------------------------
    // EGMSetupUC verified: ABB's state machine add-in and motion-program-exec pass
    // (ROB_1, id, config, device) with \Joint, \Pose or \PathCorr \APTR and \CommTimeout.
    // EGMSetupAI/GI: uncertain, no public caller found; kept as the manual's analog and
    // group input variants of EGMSetupUC.
    routine(
        r#"PROC EGMSetupUC(VAR mecunit MecUnit, VAR egmident EGMid, string ExtConfigName, string UCDevice, \switch Joint | switch Pose | switch PathCorr, \switch APTR | switch LATR, \num CommTimeout)"#,
        "Sets up an EGM process whose references come over UdpUc (UDP) from an external device.",
    )
    .names_data()
    .open_optionals(),
    routine(
        r#"PROC EGMSetupAI(VAR mecunit MecUnit, VAR egmident EGMid, string ExtConfigName, \switch Joint | switch Pose | switch PathCorr, \switch APTR | switch LATR, \signalai AiJ1orX, \signalai AiJ2orY, \signalai AiJ3orZ, \signalai AiJ4orRX, \signalai AiJ5orRY, \signalai AiJ6orRZ, \signalai AiJ7)"#,
        "Sets up an EGM process whose references are analog input signals.",
    )
    .names_data()
    .open_optionals(),
    routine(
        r#"PROC EGMSetupGI(VAR mecunit MecUnit, VAR egmident EGMid, string ExtConfigName, \switch Joint | switch Pose | switch PathCorr, \switch APTR | switch LATR, \signalgi GiJ1orX, \signalgi GiJ2orY, \signalgi GiJ3orZ, \signalgi GiJ4orRX, \signalgi GiJ5orRY, \signalgi GiJ6orRZ, \signalgi GiJ7)"#,
        "Sets up an EGM process whose references are group input signals.",
    )
    .names_data()
    .open_optionals(),
    // ---- Activation ---------------------------------------------------------------------
    // Verified: ABB's state machine add-in calls EGMActJoint and EGMActPose with \Tool,
    // \WObj, \TLoad (in this order), the convergence ranges, \LpFilter, \SampleRate and
    // \MaxSpeedDeviation; motion-program-exec and public examples add \StreamStart (first)
    // and \MaxPosDeviation; EGMActPose's four required frame arguments come after \WObj
    // (\TLoad) in every public call.
    routine(
        r#"PROC EGMActJoint(VAR egmident EGMid, \switch StreamStart, \PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, \egm_minmax J1, \egm_minmax J2, \egm_minmax J3, \egm_minmax J4, \egm_minmax J5, \egm_minmax J6, \egm_minmax J7, \num LpFilter, \num SampleRate, \num MaxPosDeviation, \num MaxSpeedDeviation)"#,
        "Activates joint guidance for an EGM process, with convergence ranges per axis.",
    )
    .open_optionals(),
    routine(
        r#"PROC EGMActPose(VAR egmident EGMid, \switch StreamStart, \PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad, pose CorrFrame, egmframetype CorrFrType, pose SensorFrame, egmframetype SensorFrType, \egm_minmax x, \egm_minmax y, \egm_minmax z, \egm_minmax rx, \egm_minmax ry, \egm_minmax rz, \num LpFilter, \num SampleRate, \num MaxPosDeviation, \num MaxSpeedDeviation)"#,
        "Activates pose guidance for an EGM process, with its correction and sensor frames.",
    )
    .open_optionals(),
    // Verified (motion-program-exec, public path-correction examples): id, a sensor
    // frame (a pose, often a tool's tframe) and \SampleRate.
    routine(
        r#"PROC EGMActMove(VAR egmident EGMid, \switch StreamStart, pose SensorFrame, \num LpFilter, \num SampleRate, \num MaxSpeedDeviation)"#,
        "Activates path correction for an EGM process (EGMMoveL, EGMMoveC).",
    )
    .open_optionals(),
    // ---- Movement -----------------------------------------------------------------------
    // Verified: ABB's state machine add-in and motion-program-exec call EGMRunJoint and
    // EGMRunPose with a stop mode, \NoWaitCond, the axis switches, \CondTime,
    // \RampInTime, \RampOutTime, \Offset (a pose for EGMRunPose) and \PosCorrGain, and
    // EGMStop with a stop mode and \RampOutTime. uncertain: EGMRunJoint's \Offset type
    // (no public caller passes it) and EGMWaitCond (no public caller).
    routine(
        r#"PROC EGMRunJoint(VAR egmident EGMid, egmstopmode Mode, \switch NoWaitCond, \switch J1, \switch J2, \switch J3, \switch J4, \switch J5, \switch J6, \switch J7, \num CondTime, \num RampInTime, \num RampOutTime, \jointtarget Offset, \num PosCorrGain)"#,
        "Moves the robot by joint references from the external device until the convergence condition holds.",
    )
    .open_optionals(),
    routine(
        r#"PROC EGMRunPose(VAR egmident EGMid, egmstopmode Mode, \switch NoWaitCond, \switch x, \switch y, \switch z, \switch Rx, \switch Ry, \switch Rz, \num CondTime, \num RampInTime, \num RampOutTime, \pose Offset, \num PosCorrGain)"#,
        "Moves the robot by pose references from the external device until the convergence condition holds.",
    )
    .open_optionals(),
    routine(
        r#"PROC EGMStop(VAR egmident EGMid, egmstopmode Mode, \num RampOutTime)"#,
        "Stops an EGM movement.",
    )
    .open_optionals(),
    routine(
        r#"PROC EGMWaitCond(VAR egmident EGMid)"#,
        "Waits until the convergence condition of an EGM movement started with \\NoWaitCond holds.",
    )
    .open_optionals(),
    // Verified (motion-program-exec, public path-correction examples): id, then
    // MoveL's/MoveC's own arguments with \WObj.
    routine(
        r#"PROC EGMMoveL(VAR egmident EGMid, robtarget ToPoint, speeddata Speed, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)"#,
        "A linear move corrected by EGM path correction.",
    )
    .open_optionals(),
    routine(
        r#"PROC EGMMoveC(VAR egmident EGMid, robtarget CirPoint, robtarget ToPoint, speeddata Speed, zonedata Zone, PERS tooldata Tool, \PERS wobjdata WObj, \PERS loaddata TLoad)"#,
        "A circular move corrected by EGM path correction.",
    )
    .open_optionals(),
    // ---- Position streaming -------------------------------------------------------------
    // Verified (ABB's state machine add-in, motion-program-exec): id and \SampleRate.
    routine(r#"PROC EGMStreamStart(VAR egmident EGMid, \num SampleRate)"#, "Starts streaming the robot's positions to the external device.")
        .open_optionals(),
    routine("PROC EGMStreamStop(VAR egmident EGMid)", "Stops streaming the robot's positions.")
        .open_optionals(),
];
