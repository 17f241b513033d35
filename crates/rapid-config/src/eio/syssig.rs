//! System inputs and outputs of the I/O configuration (`SYSSIG_IN`, `SYSSIG_OUT`): a
//! digital input that starts, stops or otherwise operates the controller on its
//! rising edge, and a digital output the controller sets to show its state.
//!
//! Sources: the types and attributes (`-Signal -Action -Arg1`, `-Status -Signal
//! -Arg2`) are those RobotStudio writes in EIO.cfg, as public tools that read and
//! write these sections show. The action and status names are those of ABB's
//! *Technical reference manual – System parameters* (topic I/O System, types System
//! Input and System Output) as we remember them; we could not confirm them from a
//! public copy.
//!
//! Every standard RobotWare 6 action and status is accepted. Those `rapid run` does not
//! simulate ([`SysAction::NotSimulated`], [`SysStatus::NotSimulated`]) are read with a
//! warning rather than refused, so a real backup runs: such an input does nothing, such
//! an output is never set by the controller.
// uncertain: every action and status name below, and the arguments each takes.

use std::ops::Range;

use super::{push, value_span, Eio, SignalType};
use crate::{CfgError, CfgFile, Instance};

/// What a system input does on its rising edge (`-Action`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SysAction {
    /// Start (restart) the NORMAL tasks where they stand.
    Start,
    /// PP to Main, then start.
    StartMain,
    /// Stop at the next instruction.
    Stop,
    /// Stop at once, the robot braking hard (modelled as Stop).
    QuickStop,
    /// Stop with a softer brake (modelled as Stop).
    SoftStop,
    /// Stop when the cycle (main) ends.
    StopCycle,
    /// Stop when the instruction under way ends (modelled as Stop: tasks always stop
    /// between instructions).
    StopInstr,
    MotorOn,
    MotorOff,
    /// Motors on, then start.
    MotorOnStart,
    /// Reset the execution error output.
    ResetError,
    /// PP to Main without starting.
    PpToMain,
    /// Reset the emergency stop: a virtual run has none, so there is nothing to reset.
    ResetEstop,
    /// A standard action `rapid run` does not simulate (its configuration spelling):
    /// accepted with a warning, it does nothing.
    NotSimulated(&'static str),
}

/// The `-Action` spellings, in EIO.cfg and ours.
const ACTIONS: &[(&str, SysAction)] = &[
    ("Start", SysAction::Start),
    ("StartMain", SysAction::StartMain),
    ("Stop", SysAction::Stop),
    ("QuickStop", SysAction::QuickStop),
    ("SoftStop", SysAction::SoftStop),
    ("StopCycle", SysAction::StopCycle),
    ("StopInstr", SysAction::StopInstr),
    ("MotorOn", SysAction::MotorOn),
    ("MotorOff", SysAction::MotorOff),
    ("MotOnStart", SysAction::MotorOnStart),
    ("ResetError", SysAction::ResetError),
    ("PpToMain", SysAction::PpToMain),
    ("ResetEstop", SysAction::ResetEstop),
];

/// Standard actions accepted but not simulated: System Restart, Interrupt (a routine
/// run at the input, `-Arg6`), loading programs, backups, speed override, simulated
/// mode, write access, energy saving, collision avoidance, limited speed.
const NOT_SIMULATED_ACTIONS: &[&str] = &[
    "SysReset",
    "Interrupt",
    "LoadStart",
    "Load",
    "Backup",
    "DisableBackup",
    "SetSpeedOverride",
    "SimMode",
    "WriteAccess",
    "EnableEnergySaving",
    "CollAvoid",
    "LimitSpeed",
];

/// What a system output shows (`-Status`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SysStatus {
    /// 1 while the program runs.
    CycleOn,
    /// 1 while the motors are on.
    MotorOn,
    /// 1 while the motors are off.
    MotorOff,
    /// As MotorOn and MotorOff, steady (no flashing states are modelled).
    MotOnState,
    MotOffState,
    /// 1 in automatic mode.
    AutoOn,
    /// 1 while the task `-Arg2` executes.
    TaskExecuting,
    /// Execution error: 1 when a task (`-Arg2`, all when not given) stopped on an error.
    Error,
    /// The run chain is closed (no emergency stop): 1 from power on.
    RunchOk,
    /// Emergency stop: 0 (never pressed in a virtual run).
    EmStop,
    /// Simulated mode (the Sim Mode input, not simulated): 0.
    SimMode,
    /// 1 while the mechanical unit `-Arg1` stands still (without `-Arg1`: while no
    /// mechanical unit moves).
    MechUnitNotMoving,
    /// 1 while the mechanical unit `-Arg1` is active (without `-Arg1`: while every one
    /// is).
    MechUnitActive,
    /// A standard status `rapid run` does not simulate (its configuration spelling):
    /// accepted with a warning, the controller never sets the output.
    NotSimulated(&'static str),
}

const STATUSES: &[(&str, SysStatus)] = &[
    ("CycleOn", SysStatus::CycleOn),
    ("MotorOn", SysStatus::MotorOn),
    ("MotorOff", SysStatus::MotorOff),
    ("MotOnState", SysStatus::MotOnState),
    ("MotOffState", SysStatus::MotOffState),
    ("AutoOn", SysStatus::AutoOn),
    ("TaskExecuting", SysStatus::TaskExecuting),
    ("Error", SysStatus::Error),
    ("RunchOk", SysStatus::RunchOk),
    ("EmStop", SysStatus::EmStop),
    ("SimMode", SysStatus::SimMode),
    ("MechUnitNotMoving", SysStatus::MechUnitNotMoving),
    ("MechUnitActive", SysStatus::MechUnitActive),
];

/// Standard statuses accepted but not simulated, with the signal type each shows on
/// (the TCP speeds are analog outputs).
const NOT_SIMULATED_STATUSES: &[(&str, SignalType)] = &[
    ("AbsAccActive", SignalType::Do),
    ("BackupErr", SignalType::Do),
    ("BackupInProgress", SignalType::Do),
    ("CollAvoid", SignalType::Do),
    ("CPUFanNotRunning", SignalType::Do),
    ("EnergySavingBlocked", SignalType::Do),
    ("LimitSpeed", SignalType::Do),
    ("MotSupOn", SignalType::Do),
    ("MotSupTrigg", SignalType::Do),
    ("PathReturnRegionError", SignalType::Do),
    ("PFError", SignalType::Do),
    ("ProdExecError", SignalType::Do),
    ("RobotNotOnPath", SignalType::Do),
    ("SimulatedIO", SignalType::Do),
    ("SMBBatteryChargeLow", SignalType::Do),
    ("TCPSpeed", SignalType::Ao),
    ("TCPSpeedRef", SignalType::Ao),
    ("TempWarning", SignalType::Do),
    ("WriteAccess", SignalType::Do),
];

/// One `SYSSIG_IN` instance.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SysInput {
    pub signal: String,
    pub action: SysAction,
    /// Start's `-Arg1`: `CONT` (continuous) or `CYCLE` (one cycle).
    pub arg1: Option<String>,
    pub line: u32,
}

/// One `SYSSIG_OUT` instance.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SysOutput {
    pub signal: String,
    pub status: SysStatus,
    /// `-Arg2`: the task (TaskExecuting, Error).
    pub task: Option<String>,
    /// `-Arg1`: the mechanical unit (MechUnitNotMoving, MechUnitActive). None: every
    /// mechanical unit of the system, so MechUnitNotMoving is 1 while none of them
    /// moves and MechUnitActive while all of them are active.
    // uncertain: the argument that names the unit, as we remember the manual; and
    // what RobotWare shows when it is left out (controller-written EIO.cfg files leave
    // it out, the manual's default is not public to us): every unit is our reading.
    pub unit: Option<String>,
    pub line: u32,
}

/// The spelling of an action as the configuration writes it.
pub fn action_name(action: SysAction) -> &'static str {
    if let SysAction::NotSimulated(name) = action {
        return name;
    }
    ACTIONS.iter().find(|(_, a)| *a == action).map_or("?", |(n, _)| n)
}

/// The spelling of a status as the configuration writes it.
pub fn status_name(status: SysStatus) -> &'static str {
    if let SysStatus::NotSimulated(name) = status {
        return name;
    }
    STATUSES.iter().find(|(_, s)| *s == status).map_or("?", |(n, _)| n)
}

/// The action of an `-Action` value, ignoring case.
fn action(text: &str) -> Option<SysAction> {
    let simulated = ACTIONS.iter().find(|(n, _)| n.eq_ignore_ascii_case(text)).map(|(_, a)| *a);
    simulated.or_else(|| {
        NOT_SIMULATED_ACTIONS.iter().find(|n| n.eq_ignore_ascii_case(text)).map(|n| SysAction::NotSimulated(n))
    })
}

/// The status of a `-Status` value, ignoring case, and the signal type it shows on.
fn status(text: &str) -> Option<(SysStatus, SignalType)> {
    let simulated = STATUSES.iter().find(|(n, _)| n.eq_ignore_ascii_case(text)).map(|(_, s)| (*s, SignalType::Do));
    simulated.or_else(|| {
        let (name, wanted) = NOT_SIMULATED_STATUSES.iter().find(|(n, _)| n.eq_ignore_ascii_case(text))?;
        Some((SysStatus::NotSimulated(name), *wanted))
    })
}

/// Reads the system inputs and outputs into `eio` (its signals read already).
pub(super) fn read(file: &CfgFile, eio: &mut Eio) {
    let mut errors = Vec::new();
    let mut warnings = Vec::new();
    for inst in file.instances("SYSSIG_IN") {
        let Some(signal) = checked_signal(inst, eio, SignalType::Di, "SYSSIG_IN", &mut errors) else { continue };
        let Some(text) = inst.value("Action") else {
            push(&mut errors, inst, None, format!("system input `{signal}` has no `-Action`"));
            continue;
        };
        let Some(action) = action(text) else {
            let names: Vec<&str> =
                ACTIONS.iter().map(|(n, _)| *n).chain(NOT_SIMULATED_ACTIONS.iter().copied()).collect();
            let message = format!("system input `{signal}`: unknown action `{text}` (one of {})", names.join(", "));
            push(&mut errors, inst, value_span(inst, "Action"), message);
            continue;
        };
        let arg1 = inst.value("Arg1").map(str::to_owned);
        // uncertain: Start, StartMain and MotOnStart take CONT or CYCLE as -Arg1.
        if let Some(arg) = &arg1 {
            let takes_mode = matches!(action, SysAction::Start | SysAction::StartMain | SysAction::MotorOnStart);
            if takes_mode && !["CONT", "CYCLE"].contains(&arg.to_ascii_uppercase().as_str()) {
                let message = format!("system input `{signal}`: `-Arg1 {arg}` is neither CONT nor CYCLE");
                push(&mut errors, inst, value_span(inst, "Arg1"), message);
                continue;
            }
        }
        if eio.sys_inputs.iter().any(|i| i.signal.eq_ignore_ascii_case(&signal)) {
            let message = format!("signal `{signal}` is a system input twice");
            push(&mut errors, inst, value_span(inst, "Signal"), message);
            continue;
        }
        if let SysAction::NotSimulated(name) = action {
            let message = format!(
                "system input `{signal}`: action `{name}` is accepted but not simulated \
                 (the input does nothing in `rapid run`)"
            );
            push(&mut warnings, inst, value_span(inst, "Action"), message);
        }
        eio.sys_inputs.push(SysInput { signal, action, arg1, line: inst.line });
    }
    for inst in file.instances("SYSSIG_OUT") {
        // The status says which signal type the output must be (a DO but for the TCP
        // speeds); an unknown status is reported against a DO.
        let found = inst.value("Status").and_then(status);
        let wanted = found.map_or(SignalType::Do, |(_, wanted)| wanted);
        let Some(signal) = checked_signal(inst, eio, wanted, "SYSSIG_OUT", &mut errors) else { continue };
        let Some(text) = inst.value("Status") else {
            push(&mut errors, inst, None, format!("system output `{signal}` has no `-Status`"));
            continue;
        };
        let Some((status, _)) = found else {
            let names: Vec<&str> =
                STATUSES.iter().map(|(n, _)| *n).chain(NOT_SIMULATED_STATUSES.iter().map(|(n, _)| *n)).collect();
            let message = format!("system output `{signal}`: unknown status `{text}` (one of {})", names.join(", "));
            push(&mut errors, inst, value_span(inst, "Status"), message);
            continue;
        };
        let task = inst.value("Arg2").map(str::to_owned);
        if status == SysStatus::TaskExecuting && task.is_none() {
            let message = format!("system output `{signal}`: TaskExecuting needs the task as `-Arg2`");
            push(&mut errors, inst, None, message);
            continue;
        }
        // MechUnitNotMoving and MechUnitActive without `-Arg1` are accepted: RobotWare
        // loads such lines (EIO.cfg files controllers wrote have them), and the output
        // then follows every mechanical unit of the system (SysOutput::unit).
        let unit = inst.value("Arg1").map(str::to_owned);
        // One output shows one status: a second would fight the first.
        if eio.sys_outputs.iter().any(|o| o.signal.eq_ignore_ascii_case(&signal)) {
            let message = format!("signal `{signal}` is a system output twice");
            push(&mut errors, inst, value_span(inst, "Signal"), message);
            continue;
        }
        if let SysStatus::NotSimulated(name) = status {
            let message = format!(
                "system output `{signal}`: status `{name}` is accepted but not simulated \
                 (the controller never sets the output)"
            );
            push(&mut warnings, inst, value_span(inst, "Status"), message);
        }
        eio.sys_outputs.push(SysOutput { signal, status, task, unit, line: inst.line });
    }
    eio.errors.append(&mut errors);
    eio.warnings.append(&mut warnings);
}

/// The instance's `-Signal`, when it names a configured signal of type `wanted`.
fn checked_signal(
    inst: &Instance,
    eio: &Eio,
    wanted: SignalType,
    section: &str,
    errors: &mut Vec<CfgError>,
) -> Option<String> {
    let Some(name) = inst.value("Signal") else {
        push(errors, inst, None, format!("a {section} instance without `-Signal`"));
        return None;
    };
    let span: Option<Range<usize>> = value_span(inst, "Signal");
    let Some(signal) = eio.signal(name) else {
        push(errors, inst, span, format!("{section} names `{name}`, which is not a configured signal"));
        return None;
    };
    if signal.signal_type != wanted {
        let (found, wanted) = (upper(signal.signal_type.rapid_type()), upper(wanted.rapid_type()));
        let message = format!(
            "{section} names `{name}`, {} {found} signal; it must be {} {wanted} signal",
            article(&found),
            article(&wanted)
        );
        push(errors, inst, span, message);
        return None;
    }
    Some(signal.name.clone())
}

/// `an` before AI and AO, `a` before the others.
fn article(signal_type: &str) -> &'static str {
    if signal_type.starts_with('A') {
        "an"
    } else {
        "a"
    }
}

/// `signaldi` → `DI`.
fn upper(rapid_type: &str) -> String {
    rapid_type.trim_start_matches("signal").to_ascii_uppercase()
}

#[cfg(test)]
mod tests {
    use super::super::read;
    use super::{SysAction, SysStatus};

    const SIGNALS: &str = "EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:

      -Name \"diStart\" -SignalType \"DI\"

      -Name \"diStop\" -SignalType \"DI\"

      -Name \"doCycleOn\" -SignalType \"DO\"

      -Name \"doExec\" -SignalType \"DO\"
";

    #[test]
    fn system_inputs_and_outputs_are_read() {
        let text = format!(
            "{SIGNALS}#
SYSSIG_IN:

      -Signal \"diStart\" -Action \"Start\" -Arg1 \"CONT\"

      -Signal \"diStop\" -Action \"stop\"
#
SYSSIG_OUT:

      -Status \"CycleOn\" -Signal \"doCycleOn\"

      -Status \"TaskExecuting\" -Signal \"doExec\" -Arg2 \"T_ROB1\"
"
        );
        let eio = read(&crate::parse(&text));
        assert!(eio.errors.is_empty(), "{:?}", eio.errors);
        let inputs: Vec<(&str, SysAction)> = eio.sys_inputs.iter().map(|i| (i.signal.as_str(), i.action)).collect();
        assert_eq!(inputs, [("diStart", SysAction::Start), ("diStop", SysAction::Stop)]);
        assert_eq!(eio.sys_inputs[0].arg1.as_deref(), Some("CONT"));
        let outputs: Vec<(SysStatus, Option<&str>)> =
            eio.sys_outputs.iter().map(|o| (o.status, o.task.as_deref())).collect();
        assert_eq!(outputs, [(SysStatus::CycleOn, None), (SysStatus::TaskExecuting, Some("T_ROB1"))]);
    }

    #[test]
    fn bad_system_signal_lines_are_findings_with_their_lines() {
        let text = format!(
            "{SIGNALS}#
SYSSIG_IN:

      -Signal \"diStart\" -Action \"Jump\"

      -Signal \"doExec\" -Action \"Stop\"

      -Signal \"diMissing\" -Action \"Stop\"

      -Signal \"diStop\" -Action \"Stop\"

      -Signal \"diStop\" -Action \"Start\"

      -Action \"Start\"
#
SYSSIG_OUT:

      -Status \"Dancing\" -Signal \"doCycleOn\"

      -Status \"CycleOn\" -Signal \"diStart\"

      -Status \"TaskExecuting\" -Signal \"doExec\"
"
        );
        let eio = read(&crate::parse(&text));
        let found: Vec<u32> = eio.errors.iter().map(|e| e.line).collect();
        assert_eq!(found, [15, 17, 19, 23, 25, 29, 31, 33], "{:?}", eio.errors);
        assert!(eio.errors[0].message.contains("unknown action `Jump`"));
        assert!(eio.errors[1].message.contains("a DO signal; it must be a DI signal"));
        assert!(eio.errors[3].message.contains("a system input twice"));
        assert_eq!(eio.sys_inputs.len(), 1);
    }

    #[test]
    fn mech_unit_outputs_without_a_unit_are_read_and_task_executing_needs_its_task() {
        // MechUnitNotMoving and MechUnitActive without -Arg1 (as controllers write
        // them) are read for every unit; TaskExecuting without -Arg2 watches nothing
        // and stays a finding (line 19).
        let text = format!(
            "{SIGNALS}#
SYSSIG_OUT:

      -Status \"MechUnitNotMoving\" -Signal \"doCycleOn\"

      -Status \"MechUnitActive\" -Signal \"doExec\" -Arg1 \"ROB_1\"

      -Status \"TaskExecuting\" -Signal \"doCycleOn\"
"
        );
        let eio = read(&crate::parse(&text));
        let outputs: Vec<(SysStatus, Option<&str>)> =
            eio.sys_outputs.iter().map(|o| (o.status, o.unit.as_deref())).collect();
        assert_eq!(outputs, [(SysStatus::MechUnitNotMoving, None), (SysStatus::MechUnitActive, Some("ROB_1"))]);
        assert!(eio.warnings.is_empty(), "{:?}", eio.warnings);
        let refused: Vec<u32> = eio.errors.iter().map(|e| e.line).collect();
        assert_eq!(refused, [19], "{:?}", eio.errors);
        assert!(eio.errors[0].message.contains("TaskExecuting needs the task as `-Arg2`"), "{:?}", eio.errors);
    }

    #[test]
    fn standard_names_not_simulated_are_read_with_warnings() {
        let text = format!(
            "{SIGNALS}
      -Name \"diReset\" -SignalType \"DI\"

      -Name \"aoSpeed\" -SignalType \"AO\"
#
SYSSIG_IN:

      -Signal \"diStart\" -Action \"resetestop\"

      -Signal \"diStop\" -Action \"SysReset\"

      -Signal \"diReset\" -Action \"Interrupt\" -Arg6 \"rInterrupt\"
#
SYSSIG_OUT:

      -Status \"SimMode\" -Signal \"doCycleOn\"

      -Status \"TCPSpeed\" -Signal \"aoSpeed\"

      -Status \"TCPSpeed\" -Signal \"doExec\"
"
        );
        let eio = read(&crate::parse(&text));
        let inputs: Vec<SysAction> = eio.sys_inputs.iter().map(|i| i.action).collect();
        let not_simulated = [SysAction::NotSimulated("SysReset"), SysAction::NotSimulated("Interrupt")];
        assert_eq!(inputs, [SysAction::ResetEstop, not_simulated[0], not_simulated[1]]);
        let outputs: Vec<SysStatus> = eio.sys_outputs.iter().map(|o| o.status).collect();
        assert_eq!(outputs, [SysStatus::SimMode, SysStatus::NotSimulated("TCPSpeed")]);
        // ResetEstop and SimMode are modelled; the others are read with a warning each.
        let warned: Vec<u32> = eio.warnings.iter().map(|w| w.line).collect();
        assert_eq!(warned, [21, 23, 29], "{:?}", eio.warnings);
        assert!(eio.warnings[0].message.contains("action `SysReset` is accepted but not simulated"));
        assert!(eio.warnings[2].message.contains("status `TCPSpeed` is accepted but not simulated"));
        // The TCP speed is an analog output: on a DO it is refused.
        let refused: Vec<u32> = eio.errors.iter().map(|e| e.line).collect();
        assert_eq!(refused, [31], "{:?}", eio.errors);
        assert!(eio.errors[0].message.contains("a DO signal; it must be an AO signal"), "{:?}", eio.errors);
    }
}
