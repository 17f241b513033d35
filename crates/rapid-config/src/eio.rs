//! The I/O configuration (`EIO.cfg`): signals, devices (with their start-up state),
//! networks and cross-connections, system inputs and outputs (`syssig`).
//!
//! Sources for the attribute names: RobotWare 6 backups write `-Device`/`-DeviceMap`,
//! RobotWare 5 backups `-Unit`/`-UnitMap` (both read, as public backups show). Analog
//! scaling uses `-MinLog -MaxLog -MinPhys -MaxPhys -MinBitVal -MaxBitVal`.

use std::ops::Range;

use crate::{CfgError, CfgFile, Instance};

pub mod syssig;

pub use syssig::{SysAction, SysInput, SysOutput, SysStatus};

/// The six signal types of `-SignalType`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SignalType {
    Di,
    Do,
    Ai,
    Ao,
    Gi,
    Go,
}

impl SignalType {
    /// `DI` → [`SignalType::Di`], ignoring case.
    pub fn parse(text: &str) -> Option<SignalType> {
        Some(match text.to_ascii_uppercase().as_str() {
            "DI" => SignalType::Di,
            "DO" => SignalType::Do,
            "AI" => SignalType::Ai,
            "AO" => SignalType::Ao,
            "GI" => SignalType::Gi,
            "GO" => SignalType::Go,
            _ => return None,
        })
    }

    /// The RAPID data type a signal of this type is in programs.
    pub fn rapid_type(self) -> &'static str {
        match self {
            SignalType::Di => "signaldi",
            SignalType::Do => "signaldo",
            SignalType::Ai => "signalai",
            SignalType::Ao => "signalao",
            SignalType::Gi => "signalgi",
            SignalType::Go => "signalgo",
        }
    }

    fn is_digital(self) -> bool {
        matches!(self, SignalType::Di | SignalType::Do)
    }

    fn is_group(self) -> bool {
        matches!(self, SignalType::Gi | SignalType::Go)
    }
}

/// Analog scaling: logical values `min_log..max_log` map to bit values
/// `min_bit_val..max_bit_val` (and physical `min_phys..max_phys`).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Analog {
    pub min_log: Option<f64>,
    pub max_log: Option<f64>,
    pub min_phys: Option<f64>,
    pub max_phys: Option<f64>,
    pub min_bit_val: Option<f64>,
    pub max_bit_val: Option<f64>,
}

/// One `EIO_SIGNAL` instance.
#[derive(Debug, Clone, PartialEq)]
pub struct Signal {
    pub name: String,
    pub signal_type: SignalType,
    /// `-Device` (RobotWare 6) or `-Unit` (RobotWare 5); none for a virtual signal.
    pub device: Option<String>,
    /// `-DeviceMap` / `-UnitMap` as written, e.g. `"0-7"`.
    pub device_map: Option<String>,
    /// The bits the map names, in map order.
    pub bits: Vec<u32>,
    /// `-Default`, the value at start.
    pub default: Option<f64>,
    /// `-Access` (`Default`, `All`, `ReadOnly`, or a configured access level).
    pub access: Option<String>,
    /// `-Label`, the signal's label text.
    pub label: Option<String>,
    pub analog: Analog,
    pub line: u32,
    pub span: Range<usize>,
}

impl Signal {
    /// The width of a group signal: the number of bits its map names.
    pub fn width(&self) -> usize {
        self.bits.len()
    }
}

/// A device (RobotWare 6: sections named `…_DEVICE`) or unit (RobotWare 5: `EIO_UNIT`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Device {
    pub name: String,
    /// The section the device is configured in (`DEVICENET_DEVICE`, `EIO_UNIT`, …).
    pub kind: String,
    /// `-Network` (RobotWare 6) or `-Bus` (RobotWare 5).
    pub network: Option<String>,
    /// Whether the device is enabled when the controller starts: RobotWare 6
    /// `-StateWhenStartup "Deactivated"` or RobotWare 5 `-Disabled` start it disabled.
    pub enabled: bool,
    pub line: u32,
}

/// An I/O network (RobotWare 6: `INDUSTRIAL_NETWORK`) or bus (RobotWare 5: `EIO_BUS`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Network {
    pub name: String,
    pub line: u32,
}

/// One actor of a cross-connection: a signal, maybe inverted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Actor {
    pub signal: String,
    pub invert: bool,
}

/// An `EIO_CROSS` instance: `-Res` is driven by `-Act1 -Oper1 -Act2 …`. Kept as data;
/// evaluating it is the I/O system's work.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CrossConnection {
    pub name: Option<String>,
    pub result: String,
    pub actors: Vec<Actor>,
    /// `operators[i]` joins `actors[i]` and `actors[i + 1]` (`AND` or `OR`); `None` when
    /// not written.
    pub operators: Vec<Option<String>>,
    pub line: u32,
}

/// The typed view of an EIO configuration.
#[derive(Debug, Clone, Default)]
pub struct Eio {
    pub signals: Vec<Signal>,
    pub devices: Vec<Device>,
    pub networks: Vec<Network>,
    pub cross: Vec<CrossConnection>,
    /// `SYSSIG_IN`: inputs that operate the controller.
    pub sys_inputs: Vec<SysInput>,
    /// `SYSSIG_OUT`: outputs that show the controller's state.
    pub sys_outputs: Vec<SysOutput>,
    /// What the view refuses (the parser's errors are in the file).
    pub errors: Vec<CfgError>,
    /// What the view accepts but `rapid run` does not simulate (standard system input
    /// actions and output statuses without a model).
    pub warnings: Vec<CfgError>,
}

impl Eio {
    /// The signal of a name, ignoring case as RAPID does.
    pub fn signal(&self, name: &str) -> Option<&Signal> {
        self.signals.iter().find(|s| s.name.eq_ignore_ascii_case(name))
    }
}

/// At most 5 actors per cross-connection (Act1..Act5).
// uncertain: the system parameters manual's limit as we remember it.
const MAX_ACTORS: usize = 5;
/// A group signal has at most 32 bits (GInputDnum/GOutputDnum reach 32).
const MAX_GROUP_BITS: usize = 32;

/// Reads the signals, devices and cross-connections of an EIO file.
pub fn read(file: &CfgFile) -> Eio {
    let mut eio = Eio::default();
    for section in &file.sections {
        let kind = section.name.to_ascii_uppercase();
        // uncertain: RobotWare 6 names every device type `<NETWORK>_DEVICE` (public
        // backups show DEVICENET_DEVICE, PROFINET_INTERNAL_ANYBUS_DEVICE, …).
        if kind == "EIO_UNIT" || kind.ends_with("_DEVICE") {
            for inst in &section.instances {
                if let Some(name) = inst.name() {
                    if eio.devices.iter().any(|d| d.name.eq_ignore_ascii_case(name)) {
                        let message = format!("I/O device `{name}` is configured twice");
                        push(&mut eio.errors, inst, value_span(inst, "Name"), message);
                        continue;
                    }
                    let network = inst.value("Network").or_else(|| inst.value("Bus")).map(str::to_owned);
                    eio.devices.push(Device {
                        name: name.to_owned(),
                        kind: section.name.clone(),
                        network,
                        enabled: starts_enabled(inst),
                        line: inst.line,
                    });
                }
            }
        }
        // uncertain: RobotWare 6 keeps networks in INDUSTRIAL_NETWORK (public backups show
        // it), RobotWare 5 buses in EIO_BUS as we remember it.
        if kind == "INDUSTRIAL_NETWORK" || kind == "EIO_BUS" {
            for inst in &section.instances {
                if let Some(name) = inst.name() {
                    if eio.networks.iter().any(|n| n.name.eq_ignore_ascii_case(name)) {
                        let message = format!("I/O network `{name}` is configured twice");
                        push(&mut eio.errors, inst, value_span(inst, "Name"), message);
                        continue;
                    }
                    eio.networks.push(Network { name: name.to_owned(), line: inst.line });
                }
            }
        }
    }
    for inst in file.instances("EIO_SIGNAL") {
        if let Some(signal) = signal(inst, &mut eio.errors) {
            if eio.signal(&signal.name).is_some() {
                let message = format!("signal `{}` is configured twice", signal.name);
                push(&mut eio.errors, inst, inst.attr("Name").map(|a| a.name_span.clone()), message);
                continue;
            }
            eio.signals.push(signal);
        }
    }
    drive_module_signals(file, &mut eio);
    let mut cross_errors = Vec::new();
    for inst in file.instances("EIO_CROSS") {
        check_cross(inst, &eio, &mut cross_errors);
        eio.cross.extend(cross(inst));
    }
    eio.errors.append(&mut cross_errors);
    check_loops(file, &mut eio);
    syssig::read(file, &mut eio);
    // Findings carry the line of their own span (a value may sit on a continuation line).
    for error in &mut eio.errors {
        error.line = file.line_of(error.span.start);
    }
    eio
}

/// The drive module's internal signals a cross-connection names (`-Act1 "DRV1BRAKE"`):
/// RobotWare configures them itself, on each drive module's internal device, so a
/// backup's EIO.cfg uses them without defining them. Each becomes a read-only digital
/// output that stays 0 (`rapid run` has no drive module), with a warning at its line.
// uncertain: the names follow RobotWare's `DRV<n><NAME>` pattern (DRV1BRAKE, DRV1K1,
// DRV1CHAIN1, …); which of them are inputs and which outputs is not known to us.
fn drive_module_signals(file: &CfgFile, eio: &mut Eio) {
    for inst in file.instances("EIO_CROSS") {
        for attr in &inst.attrs {
            let lower = attr.name.to_ascii_lowercase();
            let is_actor = lower.starts_with("act") && lower[3..].parse::<usize>().is_ok();
            let Some(value) = attr.value.as_ref().filter(|_| is_actor) else { continue };
            if !is_drive_signal(&value.text) || eio.signal(&value.text).is_some() {
                continue;
            }
            let message = format!(
                "`{}` is an internal signal of the drive module, which RobotWare configures itself: \
                 accepted, and it stays 0 in `rapid run`",
                value.text
            );
            eio.warnings.push(CfgError { line: file.line_of(value.span.start), span: value.span.clone(), message });
            eio.signals.push(Signal {
                name: value.text.clone(),
                signal_type: SignalType::Do,
                device: None,
                device_map: None,
                bits: Vec::new(),
                default: None,
                access: Some("ReadOnly".to_owned()),
                label: None,
                analog: Analog::default(),
                line: inst.line,
                span: value.span.clone(),
            });
        }
    }
}

/// `DRV1BRAKE`: `DRV`, the drive module's number, a name.
fn is_drive_signal(name: &str) -> bool {
    let Some(rest) = name.get(..3).filter(|p| p.eq_ignore_ascii_case("DRV")).map(|_| &name[3..]) else {
        return false;
    };
    let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
    digits > 0 && rest.len() > digits && rest[digits..].bytes().all(|b| b.is_ascii_alphanumeric())
}

/// A device starts disabled with `-StateWhenStartup "Deactivated"` (RobotWare 6) or the
/// `-Disabled` flag (RobotWare 5).
// uncertain: both attribute names as we remember the system parameters manuals; public
// backups rarely carry either.
fn starts_enabled(inst: &Instance) -> bool {
    let deactivated = inst.value("StateWhenStartup").is_some_and(|v| v.eq_ignore_ascii_case("Deactivated"));
    !(deactivated || inst.has("Disabled"))
}

fn push(errors: &mut Vec<CfgError>, inst: &Instance, span: Option<Range<usize>>, message: String) {
    let span = span.unwrap_or(inst.span.clone());
    errors.push(CfgError { line: inst.line, span, message });
}

/// The span of an attribute's value (or of the instance).
fn value_span(inst: &Instance, attr: &str) -> Option<Range<usize>> {
    let attr = inst.attr(attr)?;
    Some(attr.value.as_ref().map_or(attr.name_span.clone(), |v| v.span.clone()))
}

fn signal(inst: &Instance, errors: &mut Vec<CfgError>) -> Option<Signal> {
    let Some(name) = inst.name() else {
        push(errors, inst, None, "a signal without `-Name`".to_owned());
        return None;
    };
    let signal_type = match inst.value("SignalType") {
        None => {
            push(errors, inst, None, format!("signal `{name}` has no `-SignalType`"));
            return None;
        }
        Some(text) => match SignalType::parse(text) {
            Some(ty) => ty,
            None => {
                let message = format!("signal `{name}`: unknown signal type `{text}` (DI, DO, AI, AO, GI or GO)");
                push(errors, inst, value_span(inst, "SignalType"), message);
                return None;
            }
        },
    };
    let device = inst.value("Device").or_else(|| inst.value("Unit")).map(str::to_owned);
    let map_attr = if inst.has("DeviceMap") { "DeviceMap" } else { "UnitMap" };
    let device_map = inst.value(map_attr).map(str::to_owned);
    let bits = match device_map.as_deref().map(parse_map) {
        None => Vec::new(),
        Some(Ok(bits)) => bits,
        Some(Err(message)) => {
            push(errors, inst, value_span(inst, map_attr), format!("signal `{name}`: {message}"));
            Vec::new()
        }
    };
    // uncertain: the controller refuses a DI/DO mapped on more than one bit.
    if signal_type.is_digital() && bits.len() > 1 {
        let message = format!("signal `{name}`: a digital signal maps one bit, this map names {}", bits.len());
        push(errors, inst, value_span(inst, map_attr), message);
    }
    if signal_type.is_group() && bits.len() > MAX_GROUP_BITS {
        let message =
            format!("signal `{name}`: a group signal has at most {MAX_GROUP_BITS} bits, this map names {}", bits.len());
        push(errors, inst, value_span(inst, map_attr), message);
    }
    let mut number = |attr: &str| -> Option<f64> {
        let text = inst.value(attr)?;
        match text.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Some(v),
            _ => {
                push(
                    errors,
                    inst,
                    value_span(inst, attr),
                    format!("signal `{name}`: `-{attr}` is not a number: `{text}`"),
                );
                None
            }
        }
    };
    let default = number("Default");
    let analog = Analog {
        min_log: number("MinLog"),
        max_log: number("MaxLog"),
        min_phys: number("MinPhys"),
        max_phys: number("MaxPhys"),
        min_bit_val: number("MinBitVal"),
        max_bit_val: number("MaxBitVal"),
    };
    Some(Signal {
        name: name.to_owned(),
        signal_type,
        device,
        device_map,
        bits,
        default,
        access: inst.value("Access").map(str::to_owned),
        label: inst.value("Label").map(str::to_owned),
        analog,
        line: inst.line,
        span: inst.span.clone(),
    })
}

/// A device map: `5`, `0-7`, `7-0` (bits in reverse), or such items separated by `,`.
// uncertain: the reversed range and the comma list follow the system parameters manual
// as we remember it; public backups show `n` and `a-b` only.
pub fn parse_map(map: &str) -> Result<Vec<u32>, String> {
    let mut bits = Vec::new();
    for item in map.split(',') {
        let item = item.trim();
        let bad = || format!("the map `{map}` is not bits such as `0`, `0-7` or `0-3,8-11`");
        let (from, to) = match item.split_once('-') {
            Some((a, b)) => (a.trim().parse::<u32>().map_err(|_| bad())?, b.trim().parse::<u32>().map_err(|_| bad())?),
            None => {
                let bit = item.parse::<u32>().map_err(|_| bad())?;
                (bit, bit)
            }
        };
        if from.abs_diff(to) > 1024 {
            return Err(format!("the map `{map}` names more bits than any device has"));
        }
        if from <= to {
            bits.extend(from..=to);
        } else {
            bits.extend((to..=from).rev());
        }
    }
    Ok(bits)
}

fn cross(inst: &Instance) -> Option<CrossConnection> {
    let result = inst.value("Res")?.to_owned();
    let mut actors = Vec::new();
    let mut operators = Vec::new();
    for n in 1..=MAX_ACTORS {
        let Some(signal) = inst.value(&format!("Act{n}")) else { break };
        if n > 1 {
            operators.push(inst.value(&format!("Oper{}", n - 1)).map(str::to_ascii_uppercase));
        }
        actors.push(Actor { signal: signal.to_owned(), invert: inst.has(&format!("Act{n}_invert")) });
    }
    if actors.is_empty() {
        return None;
    }
    Some(CrossConnection { name: inst.name().map(str::to_owned), result, actors, operators, line: inst.line })
}

/// A cross-connection must name its result and first actor, name configured signals,
/// and join actors with `AND` or `OR`.
fn check_cross(inst: &Instance, eio: &Eio, errors: &mut Vec<CfgError>) {
    if !inst.has("Res") {
        push(errors, inst, None, "a cross-connection without `-Res`".to_owned());
    }
    if !inst.has("Act1") {
        push(errors, inst, None, "a cross-connection without `-Act1`".to_owned());
    }
    for attr in &inst.attrs {
        let lower = attr.name.to_ascii_lowercase();
        let names_signal = lower == "res" || (lower.starts_with("act") && lower[3..].parse::<usize>().is_ok());
        let is_oper = lower.starts_with("oper") && lower[4..].parse::<usize>().is_ok();
        let Some(value) = &attr.value else { continue };
        if names_signal && eio.signal(&value.text).is_none() {
            let message = format!("cross-connection names `{}`, which is not a configured signal", value.text);
            errors.push(CfgError { line: inst.line, span: value.span.clone(), message });
        }
        if is_oper && !["AND", "OR"].contains(&value.text.to_ascii_uppercase().as_str()) {
            let message = format!("cross-connection operator `{}` is neither AND nor OR", value.text);
            errors.push(CfgError { line: inst.line, span: value.span.clone(), message });
        }
    }
}

/// A cross-connection whose result drives, through a chain of others, one of its own
/// actors is a loop, which the controller refuses to start with (issue 5, item 2).
fn check_loops(file: &CfgFile, eio: &mut Eio) {
    let lower = |s: &str| s.to_ascii_lowercase();
    // For each result signal, the actors that drive it.
    let drives: Vec<(String, Vec<String>)> =
        eio.cross.iter().map(|c| (lower(&c.result), c.actors.iter().map(|a| lower(&a.signal)).collect())).collect();
    let instances: Vec<&Instance> = file.instances("EIO_CROSS").filter(|i| cross(i).is_some()).collect();
    for (idx, (result, _)) in drives.iter().enumerate() {
        // Walk back from the result's actors; reaching the result again is a loop.
        let mut stack: Vec<&str> = drives[idx].1.iter().map(String::as_str).collect();
        let mut seen: Vec<&str> = Vec::new();
        let mut looped = false;
        while let Some(signal) = stack.pop() {
            if signal == result {
                looped = true;
                break;
            }
            if seen.contains(&signal) {
                continue;
            }
            seen.push(signal);
            for (other, actors) in &drives {
                if other == signal {
                    stack.extend(actors.iter().map(String::as_str));
                }
            }
        }
        if looped {
            let Some(inst) = instances.get(idx) else { continue };
            let message =
                format!("cross-connections loop: `{}` is driven, through them, by itself", eio.cross[idx].result);
            push(&mut eio.errors, inst, value_span(inst, "Res"), message);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::read;

    #[test]
    fn networks_device_start_states_and_labels() {
        let text = "EIO:CFG_1.0:6:1::
#
INDUSTRIAL_NETWORK:

      -Name \"DeviceNet\" -Label \"DeviceNet Master/Slave Network\"
#
EIO_BUS:

      -Name \"Virtual1\"
#
DEVICENET_DEVICE:

      -Name \"d652\" -Network \"DeviceNet\" -Address 10

      -Name \"d651\" -Network \"DeviceNet\" -StateWhenStartup \"Deactivated\"
#
EIO_UNIT:

      -Name \"board9\" -UnitType \"d652\" -Bus \"Virtual1\" -Disabled
#
EIO_SIGNAL:

      -Name \"goCode\" -SignalType \"GO\" -Device \"d652\" -DeviceMap \"8-13\" -Label \"Recipe code\"
";
        let eio = read(&crate::parse(text));
        assert!(eio.errors.is_empty(), "{:?}", eio.errors);
        let networks: Vec<&str> = eio.networks.iter().map(|n| n.name.as_str()).collect();
        assert_eq!(networks, ["DeviceNet", "Virtual1"]);
        let devices: Vec<(&str, bool)> = eio.devices.iter().map(|d| (d.name.as_str(), d.enabled)).collect();
        assert_eq!(devices, [("d652", true), ("d651", false), ("board9", false)]);
        assert_eq!(eio.signal("gocode").and_then(|s| s.label.as_deref()), Some("Recipe code"));
    }

    #[test]
    fn a_device_or_network_configured_twice_is_refused_with_its_line() {
        let text = "EIO:CFG_1.0:6:1::
#
INDUSTRIAL_NETWORK:

      -Name \"DeviceNet\"

      -Name \"devicenet\"
#
DEVICENET_DEVICE:

      -Name \"d652\" -Network \"DeviceNet\"
#
EIO_UNIT:

      -Name \"D652\"
";
        let eio = read(&crate::parse(text));
        let found: Vec<(u32, &str)> = eio.errors.iter().map(|e| (e.line, e.message.as_str())).collect();
        assert_eq!(
            found,
            [(7, "I/O network `devicenet` is configured twice"), (15, "I/O device `D652` is configured twice")]
        );
        assert_eq!((eio.networks.len(), eio.devices.len()), (1, 1));
    }
}
