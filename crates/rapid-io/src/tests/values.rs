//! Values: digital 0/1, group ranges, analog limits, scaling and quantisation.

use super::*;
use crate::{quantise, to_bits, to_logical, to_physical, AnalogRange, IoError};
use SignalKind::{AI, AO, DO, GI, GO};

fn analog(name: &str, kind: SignalKind, range: AnalogRange) -> SignalDef {
    SignalDef { analog: Some(range), ..sig(name, kind) }
}

fn range(lmin: f64, lmax: f64, pmin: f64, pmax: f64, bits: u8) -> AnalogRange {
    AnalogRange { logical_min: lmin, logical_max: lmax, physical_min: pmin, physical_max: pmax, bits }
}

#[test]
fn setdo_takes_any_value_but_0_as_1() {
    let mut io = system(vec![sig("do1", DO), sig("di1", SignalKind::DI)], vec![]);
    io.set(0, 2.0, 0.0).unwrap();
    assert_eq!(val(&io, "do1"), 1.0);
    io.set(0, 0.0, 0.0).unwrap();
    io.set_delayed(0, -0.5, 0.0, 1.0).unwrap();
    io.advance(1.0);
    assert_eq!(val(&io, "do1"), 1.0);
    // The hardware side is held to 0 and 1.
    let err = io.set_input(1, 2.0, 2.0).unwrap_err();
    assert!(matches!(err, IoError::DigitalValue { .. }));
    assert_eq!(val(&io, "di1"), 0.0);
}

#[test]
fn group_range_is_0_to_2_pow_bits_minus_1() {
    let mut io = system(vec![group("go1", GO, 4), group("go32", GO, 32), group("gi1", GI, 3)], vec![]);
    let go1 = id(&io, "go1");
    io.set(go1, 15.0, 0.0).unwrap();
    assert_eq!(val(&io, "go1"), 15.0);
    for bad in [16.0, -1.0, 2.5, f64::INFINITY] {
        let err = io.set(go1, bad, 0.0).unwrap_err();
        assert_eq!(err.rapid_error(), Some("ERR_GO_LIM"), "value {bad}");
    }
    assert_eq!(val(&io, "go1"), 15.0);
    let go32 = id(&io, "go32");
    io.set(go32, 4_294_967_295.0, 0.0).unwrap();
    assert_eq!(val(&io, "go32"), 4_294_967_295.0);
    assert!(io.set(go32, 4_294_967_296.0, 0.0).is_err());
    // The hardware is held to the same width.
    let gi1 = id(&io, "gi1");
    assert_eq!(io.set_input(gi1, 7.0, 0.0), Ok(true));
    assert!(io.set_input(gi1, 8.0, 0.0).is_err());
}

#[test]
fn analog_limits_and_scaling() {
    let mut io = system(vec![analog("ao1", AO, range(0.0, 10.0, 0.0, 20.0, 0))], vec![]);
    let ao1 = id(&io, "ao1");
    io.set(ao1, 2.5, 0.0).unwrap();
    assert_eq!(val(&io, "ao1"), 2.5);
    assert_eq!(io.physical(ao1), Some(5.0));
    for bad in [10.5, -0.1, f64::NAN] {
        let err = io.set(ao1, bad, 1.0).unwrap_err();
        assert_eq!(err.rapid_error(), Some("ERR_AO_LIM"));
    }
    io.set(ao1, 10.0, 2.0).unwrap();
    assert_eq!(io.physical(ao1), Some(20.0));
}

#[test]
fn scaling_with_offset_4_to_20_ma() {
    let r = range(-10.0, 10.0, 4.0, 20.0, 0);
    assert_eq!(to_physical(&r, 0.0), 12.0);
    assert_eq!(to_physical(&r, -10.0), 4.0);
    assert_eq!(to_physical(&r, 10.0), 20.0);
    assert_eq!(to_physical(&r, 5.0), 16.0);
    assert_eq!(to_logical(&r, 12.0), 0.0);
    assert_eq!(to_logical(&r, 8.0), -5.0);
}

#[test]
fn falling_physical_range() {
    // A sensor whose physical value falls as the logical one rises.
    let r = range(0.0, 100.0, 10.0, 0.0, 0);
    assert_eq!(to_physical(&r, 25.0), 7.5);
    assert_eq!(to_logical(&r, 2.5), 75.0);
}

#[test]
fn a_converter_rounds_to_its_steps() {
    // 2 bits: 3 steps over 0..10, so the values 0, 10/3, 20/3 and 10 exist.
    let r = range(0.0, 10.0, 0.0, 10.0, 2);
    assert_eq!(to_bits(&r, 4.0), Some(1)); // 0.4 * 3 = 1.2
    assert_eq!(to_bits(&r, 5.0), Some(2)); // 1.5 rounds away from zero
    assert_eq!(to_bits(&r, 10.0), Some(3));
    assert!((quantise(&r, 4.0) - 10.0 / 3.0).abs() < 1e-12);
    let mut io = system(vec![analog("ao1", AO, r)], vec![]);
    io.set(0, 9.0, 0.0).unwrap(); // 2.7 → 3 → 10
    assert_eq!(val(&io, "ao1"), 10.0);
    assert_eq!(to_bits(&range(0.0, 1.0, 0.0, 1.0, 0), 0.5), None);
}

#[test]
fn analog_without_range_has_no_limits() {
    let mut io = system(vec![sig("ao1", AO), sig("ai1", AI)], vec![]);
    io.set(0, -1234.5, 0.0).unwrap();
    assert_eq!(io.physical(0), Some(-1234.5));
    assert_eq!(io.set_input(1, 99.0, 0.0), Ok(true));
    assert!(io.set(0, f64::NAN, 0.0).is_err());
}

#[test]
fn analog_input_from_hardware_is_range_checked() {
    let mut io = system(vec![analog("ai1", AI, range(0.0, 5.0, 0.0, 5.0, 0))], vec![]);
    assert_eq!(io.set_input(0, 3.0, 0.0), Ok(true));
    assert!(io.set_input(0, 6.0, 0.0).is_err());
    assert_eq!(val(&io, "ai1"), 3.0);
}

#[test]
fn defaults_are_the_start_values() {
    let io = system(
        vec![
            SignalDef { default: 1.0, ..sig("do1", DO) },
            SignalDef { default: 9.0, ..group("go1", GO, 4) },
            SignalDef { default: 2.0, ..analog("ao1", AO, range(0.0, 4.0, 0.0, 8.0, 0)) },
        ],
        vec![],
    );
    assert_eq!(val(&io, "DO1"), 1.0);
    assert_eq!(val(&io, "go1"), 9.0);
    assert_eq!(io.physical(2), Some(4.0));
    assert!(io.changes().is_empty());
}
