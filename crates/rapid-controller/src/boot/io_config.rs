//! The I/O system of a configuration: EIO.cfg's signals, devices, networks and
//! cross-connections (read by `rapid-config`) turned into `rapid-io`'s definitions.

use rapid_config::eio::{Eio, SignalType};
use rapid_io::{Access, AnalogRange, CrossConnection, CrossOp, DeviceDef, IoSystem, SignalDef, SignalKind};

/// The I/O system EIO.cfg describes, or why it cannot start (the message names the
/// signal or cross-connection and its line).
pub fn io_system(eio: &Eio) -> Result<IoSystem, String> {
    let defs: Vec<SignalDef> = eio.signals.iter().map(signal_def).collect();
    let crosses: Vec<CrossConnection> = eio.cross.iter().map(cross_connection).collect();
    let networks = eio.networks.iter().map(|n| n.name.clone()).collect();
    IoSystem::with_units(defs, crosses, devices(eio), networks).map_err(|err| format!("EIO.cfg: {err}"))
}

/// The configured devices, and one enabled device for every device name a signal uses
/// without a device section.
// uncertain: the controller refuses a signal on a device that is not configured; we keep
// such configurations running (many hand-written EIO.cfg files list only signals).
fn devices(eio: &Eio) -> Vec<DeviceDef> {
    let mut devices: Vec<DeviceDef> = eio
        .devices
        .iter()
        .map(|d| DeviceDef { name: d.name.clone(), network: d.network.clone(), enabled: d.enabled })
        .collect();
    for signal in &eio.signals {
        let Some(name) = &signal.device else { continue };
        if !devices.iter().any(|d| d.name.eq_ignore_ascii_case(name)) {
            devices.push(DeviceDef::new(name, None));
        }
    }
    devices
}

fn signal_def(signal: &rapid_config::eio::Signal) -> SignalDef {
    let mut def = SignalDef::new(&signal.name, kind(signal.signal_type));
    def.default = signal.default.unwrap_or(0.0);
    def.access = access(signal.access.as_deref());
    def.device = signal.device.clone();
    def.label = signal.label.clone().unwrap_or_default();
    def.start_bit = signal.bits.first().copied();
    if matches!(def.kind, SignalKind::GI | SignalKind::GO) {
        def.group_bits = u8::try_from(signal.width()).unwrap_or(32).clamp(1, 32);
    }
    if matches!(def.kind, SignalKind::AI | SignalKind::AO) {
        def.analog = analog(&signal.analog);
    }
    def
}

fn kind(signal_type: SignalType) -> SignalKind {
    match signal_type {
        SignalType::Di => SignalKind::DI,
        SignalType::Do => SignalKind::DO,
        SignalType::Ai => SignalKind::AI,
        SignalType::Ao => SignalKind::AO,
        SignalType::Gi => SignalKind::GI,
        SignalType::Go => SignalKind::GO,
    }
}

/// `-Access`: "ReadOnly", "All", or the name of an EIO_ACCESS level; without it, Default.
// uncertain: custom access levels are not read from EIO_ACCESS yet; RAPID may write them.
fn access(level: Option<&str>) -> Access {
    match level {
        None => Access::Default,
        Some(name) if name.eq_ignore_ascii_case("ReadOnly") => Access::ReadOnly,
        Some(name) if name.eq_ignore_ascii_case("All") => Access::All,
        Some(name) if name.eq_ignore_ascii_case("Default") => Access::Default,
        Some(name) => Access::Custom { name: name.to_string(), rapid: true },
    }
}

/// The logical and physical ranges; a converter of `-MinBitVal..-MaxBitVal` steps is
/// `bits` wide.
fn analog(a: &rapid_config::eio::Analog) -> Option<AnalogRange> {
    let (logical_min, logical_max) = (a.min_log?, a.max_log?);
    let bits = match (a.min_bit_val, a.max_bit_val) {
        (Some(min), Some(max)) if max > min => ((max - min + 1.0).log2().ceil() as u8).min(32),
        _ => 0,
    };
    Some(AnalogRange {
        logical_min,
        logical_max,
        physical_min: a.min_phys.unwrap_or(logical_min),
        physical_max: a.max_phys.unwrap_or(logical_max),
        bits,
    })
}

/// `-Res -Act1 -Oper1 -Act2 … -ActN_invert`.
// uncertain: an actor pair without `-OperN` is joined with AND.
fn cross_connection(cross: &rapid_config::eio::CrossConnection) -> CrossConnection {
    let terms = cross.actors.iter().map(|actor| (actor.signal.clone(), actor.invert)).collect::<Vec<_>>();
    let ops = (0..terms.len().saturating_sub(1))
        .map(|i| match cross.operators.get(i).cloned().flatten() {
            Some(op) if op.eq_ignore_ascii_case("OR") => CrossOp::Or,
            _ => CrossOp::And,
        })
        .collect();
    CrossConnection { result: cross.result.clone(), terms, ops }
}
