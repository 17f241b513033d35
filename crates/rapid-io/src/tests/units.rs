//! Devices, networks and analog interrupt conditions, worked by hand.

use super::{id, sig, val};
use crate::{
    AioDirection, AnalogTrigger, ConfigError, DeviceDef, IoError, IoSystem, SignalDef, SignalKind, UnitError,
    LOCAL_NETWORK,
};

fn on(name: &str, kind: SignalKind, device: &str) -> SignalDef {
    SignalDef { device: Some(device.to_string()), ..sig(name, kind) }
}

/// do1 and di1 on d1 (network Net1), do2 on d2 (disabled at start), do3 virtual.
fn cell() -> IoSystem {
    let defs = vec![
        on("do1", SignalKind::DO, "d1"),
        on("di1", SignalKind::DI, "d1"),
        on("do2", SignalKind::DO, "d2"),
        sig("do3", SignalKind::DO),
    ];
    let d2 = DeviceDef { enabled: false, ..DeviceDef::new("d2", Some("Net1")) };
    match IoSystem::with_units(defs, Vec::new(), vec![DeviceDef::new("d1", Some("Net1")), d2], Vec::new()) {
        Ok(io) => io,
        Err(e) => panic!("configuration refused: {e}"),
    }
}

#[test]
fn networks_are_the_configured_ones_those_devices_name_and_local() {
    let io = cell();
    assert_eq!(io.units().networks(), ["Net1".to_string(), LOCAL_NETWORK.to_string()]);
    assert!(io.units().has_network("net1"));
    assert!(!io.units().has_network("Net2"));
}

#[test]
fn a_disabled_device_refuses_orders_and_reads_and_ignores_its_inputs() {
    let mut io = cell();
    let (do1, di1, do2, do3) = (id(&io, "do1"), id(&io, "di1"), id(&io, "do2"), id(&io, "do3"));
    assert!(!io.is_running(do2));
    assert!(matches!(io.set(do2, 1.0, 0.0), Err(IoError::NotRunning { .. })));
    assert_eq!(io.set(do1, 1.0, 0.0), Ok(()));
    assert_eq!(io.set_device_enabled("D1", false, 1.0), Ok(()));
    assert!(matches!(io.read(do1), Err(IoError::NotRunning { .. })));
    assert_eq!(io.read(do3), Ok(0.0));
    assert_eq!(io.set_input(di1, 1.0, 1.5), Ok(false));
    assert_eq!(io.set_device_enabled("d1", true, 2.0), Ok(()));
    assert_eq!(io.read(do1), Ok(1.0));
    assert_eq!(val(&io, "di1"), 0.0);
    assert_eq!(io.set_device_enabled("d9", true, 2.0), Err(UnitError::UnknownDevice("d9".to_string())));
    assert_eq!(IoError::NotRunning { signal: "a".into(), device: "b".into() }.rapid_error(), Some("ERR_NORUNUNIT"));
}

#[test]
fn disabling_cancels_pending_pulses() {
    let mut io = cell();
    let do1 = id(&io, "do1");
    assert_eq!(io.pulse(do1, true, Some(1.0), 0.0), Ok(()));
    assert_eq!(io.set_device_enabled("d1", false, 0.5), Ok(()));
    io.advance(2.0);
    assert_eq!(io.set_device_enabled("d1", true, 2.0), Ok(()));
    assert_eq!(io.read(do1), Ok(1.0));
    assert_eq!(io.next_event_time(), None);
}

#[test]
fn a_signal_on_an_unknown_device_or_a_duplicate_device_is_a_load_error() {
    let unknown = IoSystem::with_units(vec![on("do1", SignalKind::DO, "dx")], Vec::new(), Vec::new(), Vec::new());
    assert!(matches!(unknown, Err(ConfigError::Units(UnitError::SignalDevice { .. }))));
    let twice = vec![DeviceDef::new("d1", None), DeviceDef::new("D1", None)];
    let duplicate = IoSystem::with_units(Vec::new(), Vec::new(), twice, Vec::new());
    assert!(matches!(duplicate, Err(ConfigError::Units(UnitError::Duplicate(_)))));
}

fn trigger(condition: f64, high: f64, low: f64, delta: f64, direction: AioDirection) -> AnalogTrigger {
    match AnalogTrigger::new(condition, high, low, delta, direction, 0.0) {
        Ok(t) => t,
        Err(e) => panic!("refused: {e}"),
    }
}

#[test]
fn the_manuals_between_example_with_dpos() {
    // AIO_BETWEEN 2.2..6.1, delta 1, \DPos, reference 0: 3 fires; 3.5 is within 1;
    // 5.5 fires; 7 is outside; 4 is stored (down 1.5) without interrupt; 4.8 is only
    // 0.8 up from 4; 5.2 is 1.2 up from 4 and fires.
    let mut t = trigger(5.0, 6.1, 2.2, 1.0, AioDirection::Pos);
    let fired: Vec<bool> = [3.0, 3.5, 5.5, 7.0, 4.0, 4.8, 5.2].iter().map(|&v| t.sample(v)).collect();
    assert_eq!(fired, [true, false, true, false, false, false, true]);
}

#[test]
fn conditions_and_their_limits() {
    let mut outside = trigger(6.0, 5.0, 1.0, 0.0, AioDirection::Both);
    let fired: Vec<bool> = [0.5, 3.0, 6.0, 6.0, 5.0].iter().map(|&v| outside.sample(v)).collect();
    assert_eq!(fired, [true, false, true, false, false]);
    let mut neg = trigger(7.0, 0.0, 0.0, 0.0, AioDirection::Neg);
    let fired: Vec<bool> = [1.0, 0.5, 0.5, 2.0, -1.0].iter().map(|&v| neg.sample(v)).collect();
    assert_eq!(fired, [false, true, false, false, true]);
    assert!(AnalogTrigger::new(0.0, 1.0, 0.0, 0.0, AioDirection::Both, 0.0).is_err());
    assert!(AnalogTrigger::new(5.0, 1.0, 2.0, 0.0, AioDirection::Both, 0.0).is_err());
    assert!(AnalogTrigger::new(1.0, 1.0, 2.0, 0.0, AioDirection::Both, 0.0).is_ok());
    assert!(AnalogTrigger::new(7.0, 0.0, 0.0, -0.5, AioDirection::Both, 0.0).is_err());
}
