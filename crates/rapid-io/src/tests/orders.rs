//! Program orders in time: pulses, delayed changes, cancelling, limits, order of changes.

use super::*;
use crate::{Access, IoError, MAX_DELAYED, MAX_PULSING};
use SignalKind::{DI, DO, GO};

fn one_do() -> IoSystem {
    system(vec![sig("do1", DO)], vec![])
}

#[test]
fn pulse_default_is_0_2_s_and_restores() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.pulse(do1, false, None, 1.0).unwrap();
    assert_eq!(val(&io, "do1"), 1.0);
    assert_eq!(io.next_event_time(), Some(1.2));
    io.advance(1.19);
    assert_eq!(val(&io, "do1"), 1.0);
    io.advance(1.2);
    assert_eq!(val(&io, "do1"), 0.0);
    assert_eq!(io.next_event_time(), None);
    assert_eq!(log(&io), vec![entry(1.0, "do1", 0.0, 1.0, Cause::Order), entry(1.2, "do1", 1.0, 0.0, Cause::PulseEnd)]);
}

#[test]
fn pulse_without_high_inverts_a_high_signal() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.set(do1, 1.0, 0.0).unwrap();
    io.pulse(do1, false, Some(0.5), 1.0).unwrap();
    assert_eq!(val(&io, "do1"), 0.0);
    io.advance(1.5);
    assert_eq!(val(&io, "do1"), 1.0);
}

#[test]
fn pulse_high_on_a_high_signal_stays_high_then_drops() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.set(do1, 1.0, 0.0).unwrap();
    io.pulse(do1, true, Some(0.3), 1.0).unwrap();
    assert_eq!(val(&io, "do1"), 1.0);
    io.advance(1.3);
    assert_eq!(val(&io, "do1"), 0.0);
    // No change at 1.0: the signal was high already.
    assert_eq!(log(&io), vec![entry(0.0, "do1", 0.0, 1.0, Cause::Order), entry(1.3, "do1", 1.0, 0.0, Cause::PulseEnd)]);
}

#[test]
fn pulse_high_on_a_low_signal() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.pulse(do1, true, Some(2.0), 0.0).unwrap();
    assert_eq!(val(&io, "do1"), 1.0);
    io.advance(1.999);
    assert_eq!(val(&io, "do1"), 1.0);
    io.advance(2.0);
    assert_eq!(val(&io, "do1"), 0.0);
}

#[test]
fn a_second_pulse_restarts_the_first() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.pulse(do1, false, Some(1.0), 0.0).unwrap();
    io.pulse(do1, false, Some(1.0), 0.5).unwrap();
    assert_eq!(val(&io, "do1"), 1.0);
    io.advance(1.0);
    assert_eq!(val(&io, "do1"), 1.0);
    io.advance(1.5);
    assert_eq!(val(&io, "do1"), 0.0);
    assert_eq!(log(&io).len(), 2);
}

#[test]
fn delayed_change_happens_at_its_time_even_if_advanced_past() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.set_delayed(do1, 1.0, 0.0, 0.5).unwrap();
    io.advance(0.4);
    assert_eq!(val(&io, "do1"), 0.0);
    io.advance(2.0);
    assert_eq!(val(&io, "do1"), 1.0);
    assert_eq!(log(&io), vec![entry(0.5, "do1", 0.0, 1.0, Cause::Delayed)]);
    assert_eq!(io.now(), 2.0);
}

#[test]
fn a_new_order_cancels_a_delayed_one() {
    // §2.10: SetDO \SDelay followed by another order before the delay runs out: the delayed
    // change is never carried out.
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.set_delayed(do1, 1.0, 0.0, 1.0).unwrap();
    io.set(do1, 0.0, 0.5).unwrap();
    io.advance(3.0);
    assert_eq!(val(&io, "do1"), 0.0);
    assert!(log(&io).is_empty());
    assert_eq!(io.next_event_time(), None);
}

#[test]
fn a_new_delayed_order_replaces_the_old_one() {
    let mut io = system(vec![group("go1", GO, 4)], vec![]);
    let go1 = id(&io, "go1");
    io.set_delayed(go1, 5.0, 0.0, 1.0).unwrap();
    io.set_delayed(go1, 7.0, 0.2, 1.0).unwrap();
    io.advance(1.0);
    assert_eq!(val(&io, "go1"), 0.0);
    io.advance(1.2);
    assert_eq!(val(&io, "go1"), 7.0);
    assert_eq!(log(&io), vec![entry(1.2, "go1", 0.0, 7.0, Cause::Delayed)]);
}

#[test]
fn an_order_cancels_the_end_of_a_pulse() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.pulse(do1, false, None, 0.0).unwrap();
    io.set(do1, 1.0, 0.1).unwrap();
    io.advance(1.0);
    assert_eq!(val(&io, "do1"), 1.0);
    assert_eq!(io.pulsing(), 0);
}

#[test]
fn invert_flips_and_cancels() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.invert(do1, 0.0).unwrap();
    assert_eq!(val(&io, "do1"), 1.0);
    io.set_delayed(do1, 1.0, 0.1, 0.5).unwrap();
    io.invert(do1, 0.2).unwrap();
    io.advance(1.0);
    assert_eq!(val(&io, "do1"), 0.0);
    assert_eq!(log(&io).len(), 2);
}

#[test]
fn due_changes_apply_before_a_later_order_and_ties_keep_issue_order() {
    let mut io = system(vec![sig("do1", DO), sig("do2", DO), sig("do3", DO)], vec![]);
    let (do1, do2, do3) = (id(&io, "do1"), id(&io, "do2"), id(&io, "do3"));
    io.set_delayed(do2, 1.0, 0.0, 1.0).unwrap();
    io.set_delayed(do1, 1.0, 0.0, 1.0).unwrap();
    io.set(do3, 1.0, 2.0).unwrap();
    let names: Vec<(f64, String)> = log(&io).into_iter().map(|e| (e.0, e.1)).collect();
    assert_eq!(names, vec![(1.0, "do2".to_string()), (1.0, "do1".to_string()), (2.0, "do3".to_string())]);
}

#[test]
fn time_never_runs_backwards() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    io.advance(5.0);
    io.set(do1, 1.0, 3.0).unwrap();
    assert_eq!(log(&io), vec![entry(5.0, "do1", 0.0, 1.0, Cause::Order)]);
}

#[test]
fn at_most_ten_signals_pulse_at_once() {
    let defs = (0..=MAX_PULSING).map(|i| sig(&format!("do{i}"), DO)).collect();
    let mut io = system(defs, vec![]);
    for i in 0..MAX_PULSING {
        io.pulse(i as SignalId, false, Some(1.0), 0.0).unwrap();
    }
    let last = MAX_PULSING as SignalId;
    let err = io.pulse(last, false, Some(1.0), 0.0).unwrap_err();
    assert!(matches!(err, IoError::TooManyPulses { .. }));
    assert_eq!(err.rapid_error(), None);
    assert_eq!(io.value(last), Some(0.0));
    // Pulsing one of the ten again replaces its own pulse, so it is allowed.
    io.pulse(0, false, Some(1.0), 0.5).unwrap();
    // Nine end at 1.0; then there is room.
    io.pulse(last, false, Some(1.0), 1.0).unwrap();
    assert_eq!(io.value(last), Some(1.0));
    assert_eq!(io.pulsing(), 2);
}

#[test]
fn at_most_twenty_signals_have_a_delayed_change() {
    let defs = (0..=MAX_DELAYED).map(|i| sig(&format!("do{i}"), DO)).collect();
    let mut io = system(defs, vec![]);
    for i in 0..MAX_DELAYED {
        io.set_delayed(i as SignalId, 1.0, 0.0, 1.0).unwrap();
    }
    let last = MAX_DELAYED as SignalId;
    let err = io.set_delayed(last, 1.0, 0.0, 1.0).unwrap_err();
    assert!(matches!(err, IoError::TooManyDelayed { .. }));
    assert_eq!(io.delayed(), MAX_DELAYED);
    // A direct order is no delayed change: still allowed, and it frees a place.
    io.set(0, 1.0, 0.1).unwrap();
    io.set_delayed(last, 1.0, 0.1, 1.0).unwrap();
    io.advance(1.1);
    assert_eq!(io.value(last), Some(1.0));
    assert_eq!(io.delayed(), 0);
}

#[test]
fn wrong_kinds_are_refused() {
    let mut io = system(vec![sig("di1", DI), sig("do1", DO), group("go1", GO, 8), sig("ao1", SignalKind::AO)], vec![]);
    let kind = |r: Result<(), IoError>| matches!(r, Err(IoError::WrongKind { .. }));
    assert!(kind(io.set(id(&io, "di1"), 1.0, 0.0)));
    assert!(kind(io.pulse(id(&io, "go1"), false, None, 0.0)));
    assert!(kind(io.set_delayed(id(&io, "ao1"), 1.0, 0.0, 1.0)));
    assert!(kind(io.invert(id(&io, "go1"), 0.0)));
    assert!(matches!(io.set_input(id(&io, "do1"), 1.0, 0.0), Err(IoError::WrongKind { .. })));
    assert!(matches!(io.set(99, 1.0, 0.0), Err(IoError::UnknownSignal(99))));
    assert!(io.changes().is_empty());
}

#[test]
fn read_only_outputs_refuse_rapid_but_inputs_take_hardware() {
    let ro = |name: &str, kind| SignalDef { access: Access::ReadOnly, ..sig(name, kind) };
    let mut io = system(vec![ro("do1", DO), ro("di1", DI)], vec![]);
    let err = io.set(id(&io, "do1"), 1.0, 0.0).unwrap_err();
    assert_eq!(err.rapid_error(), Some("ERR_SIG_NOT_VALID"));
    assert!(io.pulse(id(&io, "do1"), false, None, 0.0).is_err());
    assert_eq!(io.set_input(id(&io, "di1"), 1.0, 0.0), Ok(true));
    assert_eq!(val(&io, "di1"), 1.0);
    assert_eq!(val(&io, "do1"), 0.0);
}

#[test]
fn bad_times_are_refused() {
    let mut io = one_do();
    let do1 = id(&io, "do1");
    for bad in [0.0, -1.0, 2000.5, f64::NAN] {
        let err = io.pulse(do1, false, Some(bad), 0.0).unwrap_err();
        assert_eq!(err.rapid_error(), Some("ERR_ARGVALERR"));
        assert!(io.set_delayed(do1, 1.0, 0.0, bad).is_err());
    }
    assert!(io.changes().is_empty());
    io.set_delayed(do1, 1.0, 0.0, 2000.0).unwrap();
    assert_eq!(io.next_event_time(), Some(2000.0));
}

#[test]
fn drain_empties_the_log() {
    let mut io = one_do();
    io.set(0, 1.0, 0.0).unwrap();
    assert_eq!(io.drain_changes().len(), 1);
    assert!(io.changes().is_empty());
    // Setting the value it has is no change.
    io.set(0, 1.0, 1.0).unwrap();
    assert!(io.changes().is_empty());
}
