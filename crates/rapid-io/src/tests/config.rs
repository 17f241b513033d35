//! Load errors of the configuration.

use super::*;
use crate::{AnalogRange, ConfigError};
use CrossOp::{And, Or};
use SignalKind::{AI, DI, DO, GO};

fn refused(defs: Vec<SignalDef>, crosses: Vec<CrossConnection>) -> ConfigError {
    match IoSystem::new(defs, crosses) {
        Ok(_) => panic!("configuration accepted"),
        Err(e) => e,
    }
}

#[test]
fn duplicate_names_ignore_case() {
    let err = refused(vec![sig("do1", DO), sig("di1", DI), sig("DO1", DO)], vec![]);
    assert_eq!(err, ConfigError::DuplicateSignal { index: 2, name: "DO1".to_string() });
    assert_eq!(err.to_string(), "signal `DO1` is defined more than once");
}

#[test]
fn bad_signal_definitions() {
    let bad = |def: SignalDef| matches!(refused(vec![def], vec![]), ConfigError::BadSignal { .. });
    assert!(bad(group("go1", GO, 0)));
    assert!(bad(group("go1", GO, 33)));
    assert!(bad(SignalDef { default: 16.0, ..group("go1", GO, 4) }));
    assert!(bad(SignalDef { default: 2.0, ..sig("do1", DO) }));
    assert!(bad(sig("", DO)));
    let range = AnalogRange { logical_min: 5.0, logical_max: 5.0, physical_min: 0.0, physical_max: 1.0, bits: 0 };
    assert!(bad(SignalDef { analog: Some(range), ..sig("ai1", AI) }));
    let range = AnalogRange { logical_max: 10.0, ..range };
    assert!(bad(SignalDef { analog: Some(range), default: 11.0, ..sig("ai1", AI) }));
}

#[test]
fn cross_with_unknown_signal() {
    let err = refused(vec![sig("do1", DO)], vec![cross("do1", &[("di9", false)], &[])]);
    assert_eq!(err, ConfigError::UnknownCrossSignal { index: 0, name: "di9".to_string() });
    assert_eq!(err.to_string(), "cross-connection 1 names `di9`, which is not a defined signal");
    let err = refused(vec![sig("di1", DI)], vec![cross("do7", &[("di1", false)], &[])]);
    assert!(matches!(err, ConfigError::UnknownCrossSignal { .. }));
}

#[test]
fn cross_shape_errors() {
    let defs = || vec![sig("do1", DO), sig("di1", DI), sig("di2", DI), group("go1", GO, 2)];
    let shape = |c: CrossConnection| matches!(refused(defs(), vec![c]), ConfigError::BadCross { .. });
    assert!(shape(cross("do1", &[], &[])));
    assert!(shape(cross("do1", &[("di1", false), ("di2", false)], &[])));
    assert!(shape(cross("do1", &[("di1", false)], &[And])));
    assert!(shape(cross("go1", &[("di1", false)], &[])));
    let six = [("di1", false); 6];
    assert!(shape(cross("do1", &six, &[Or; 5])));
    // Five actors are the most EIO_CROSS holds, and are fine.
    assert!(IoSystem::new(defs(), vec![cross("do1", &six[..5], &[Or; 4])]).is_ok());
}

#[test]
fn two_signals_driving_each_other_are_a_loop() {
    // §2.10's example of a forbidden loop: di2 from di1 and di1 from di2.
    let err = refused(
        vec![sig("di1", DI), sig("di2", DI)],
        vec![cross("di2", &[("di1", false)], &[]), cross("di1", &[("di2", false)], &[])],
    );
    let ConfigError::CrossLoop { path, .. } = &err else { panic!("not a loop: {err}") };
    assert_eq!(path, &["di1", "di2", "di1"]);
    assert!(err.to_string().contains("closes a loop: di1 -> di2 -> di1"));
}

#[test]
fn a_longer_loop_through_an_and() {
    let err = refused(
        vec![sig("di1", DI), sig("do1", DO), sig("do2", DO), sig("do3", DO), sig("do4", DO)],
        vec![
            cross("do4", &[("di1", false)], &[]),
            cross("do2", &[("do1", false), ("di1", false)], &[And]),
            cross("do3", &[("do2", true)], &[]),
            cross("do1", &[("di1", false), ("do3", false)], &[Or]),
        ],
    );
    let ConfigError::CrossLoop { path, .. } = &err else { panic!("not a loop: {err}") };
    assert_eq!(path, &["do1", "do2", "do3", "do1"]);
}

#[test]
fn a_signal_feeding_itself_is_a_loop() {
    let err =
        refused(vec![sig("do1", DO), sig("di1", DI)], vec![cross("do1", &[("di1", false), ("do1", false)], &[And])]);
    assert_eq!(err, ConfigError::CrossLoop { index: 0, path: vec!["do1".to_string(), "do1".to_string()] });
}

#[test]
fn a_diamond_is_no_loop() {
    let io = IoSystem::new(
        vec![sig("di1", DI), sig("do1", DO), sig("do2", DO), sig("do3", DO)],
        vec![
            cross("do1", &[("di1", false)], &[]),
            cross("do2", &[("di1", true)], &[]),
            cross("do3", &[("do1", false), ("do2", false)], &[And]),
        ],
    );
    assert!(io.is_ok());
}
