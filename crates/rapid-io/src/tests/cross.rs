//! Cross-connections at run time: the examples of §2.10, AND/OR/NOT, chains, shared results.

use super::*;
use CrossOp::{And, Or};
use SignalKind::{DI, DO};

#[test]
fn manual_chain_di1_di2_di3_do4() {
    // §2.10: di2=di1, di3=di2, do4=di2; a change of di1 reaches di2, di3 and do4.
    let mut io = system(
        vec![sig("di1", DI), sig("di2", DI), sig("di3", DI), sig("do4", DO)],
        vec![
            cross("di2", &[("di1", false)], &[]),
            cross("di3", &[("di2", false)], &[]),
            cross("do4", &[("di2", false)], &[]),
        ],
    );
    assert_eq!(io.set_input(id(&io, "di1"), 1.0, 1.0), Ok(true));
    assert_eq!(
        log(&io),
        vec![
            entry(1.0, "di1", 0.0, 1.0, Cause::Hardware),
            entry(1.0, "di2", 0.0, 1.0, Cause::Cross),
            entry(1.0, "di3", 0.0, 1.0, Cause::Cross),
            entry(1.0, "do4", 0.0, 1.0, Cause::Cross),
        ]
    );
    // di2's physical channel is disconnected: the hardware cannot change it.
    assert!(io.is_cross_result(id(&io, "di2")));
    assert_eq!(io.set_input(id(&io, "di2"), 0.0, 2.0), Ok(false));
    assert_eq!(val(&io, "di2"), 1.0);
    assert_eq!(log(&io).len(), 4);
}

#[test]
fn manual_shared_result_takes_the_last_activated() {
    // §2.10: do8=do7 and do8=di5. Setting do7 sets do8; then di5 going to 0 resets do8
    // although do7 is still 1.
    let mut io = system(
        vec![sig("do7", DO), sig("di5", DI), sig("do8", DO)],
        vec![cross("do8", &[("do7", false)], &[]), cross("do8", &[("di5", false)], &[])],
    );
    io.set(id(&io, "do7"), 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do8"), 1.0);
    io.set_input(id(&io, "di5"), 1.0, 1.0).unwrap();
    assert_eq!(val(&io, "do8"), 1.0);
    io.set_input(id(&io, "di5"), 0.0, 2.0).unwrap();
    assert_eq!(val(&io, "do8"), 0.0);
    assert_eq!(val(&io, "do7"), 1.0);
}

#[test]
fn manual_and_example() {
    // §2.10: do5 = di6 AND do1.
    let mut io = system(
        vec![sig("di6", DI), sig("do1", DO), sig("do5", DO)],
        vec![cross("do5", &[("di6", false), ("do1", false)], &[And])],
    );
    io.set_input(id(&io, "di6"), 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do5"), 0.0);
    io.set(id(&io, "do1"), 1.0, 1.0).unwrap();
    assert_eq!(val(&io, "do5"), 1.0);
    io.set(id(&io, "do1"), 0.0, 2.0).unwrap();
    assert_eq!(val(&io, "do5"), 0.0);
}

#[test]
fn not_or_holds_from_start() {
    // do3 = NOT di1 OR di2: with both inputs 0 at start, do3 is 1 at once.
    let mut io = system(
        vec![sig("di1", DI), sig("di2", DI), sig("do3", DO)],
        vec![cross("do3", &[("di1", true), ("di2", false)], &[Or])],
    );
    assert_eq!(val(&io, "do3"), 1.0);
    assert!(io.changes().is_empty());
    io.set_input(id(&io, "di1"), 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do3"), 0.0);
    io.set_input(id(&io, "di2"), 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do3"), 1.0);
}

#[test]
fn and_binds_tighter_than_or() {
    // do9 = di1 OR di2 AND di3 with di1=1, di2=0, di3=0: 1 OR (0 AND 0) = 1, where
    // left-to-right (1 OR 0) AND 0 would give 0.
    let mut io = system(
        vec![sig("di1", DI), sig("di2", DI), sig("di3", DI), sig("do9", DO)],
        vec![cross("do9", &[("di1", false), ("di2", false), ("di3", false)], &[Or, And])],
    );
    io.set_input(0, 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do9"), 1.0);
    io.set_input(0, 0.0, 0.0).unwrap();
    io.set_input(1, 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do9"), 0.0);
    io.set_input(2, 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do9"), 1.0);
}

#[test]
fn a_pulse_travels_along_a_chain_as_value_changes() {
    // do2 = do1, di3 = do2: the results follow do1's real changes, at their times.
    let mut io = system(
        vec![sig("do1", DO), sig("do2", DO), sig("di3", DI)],
        vec![cross("di3", &[("do2", false)], &[]), cross("do2", &[("do1", false)], &[])],
    );
    io.pulse(id(&io, "do1"), false, None, 0.0).unwrap();
    io.advance(1.0);
    assert_eq!(
        log(&io),
        vec![
            entry(0.0, "do1", 0.0, 1.0, Cause::Order),
            entry(0.0, "do2", 0.0, 1.0, Cause::Cross),
            entry(0.0, "di3", 0.0, 1.0, Cause::Cross),
            entry(0.2, "do1", 1.0, 0.0, Cause::PulseEnd),
            entry(0.2, "do2", 1.0, 0.0, Cause::Cross),
            entry(0.2, "di3", 1.0, 0.0, Cause::Cross),
        ]
    );
}

#[test]
fn a_diamond_is_evaluated_once_without_a_glitch() {
    // b = a, c = NOT a, d = b AND c. At start b=0, c=1, d=0. When a goes to 1, b=1 and c=0,
    // so d stays 0; evaluating d between the two would flash it to 1.
    let mut io = system(
        vec![sig("a", DI), sig("b", DO), sig("c", DO), sig("d", DO)],
        vec![
            cross("d", &[("b", false), ("c", false)], &[And]),
            cross("b", &[("a", false)], &[]),
            cross("c", &[("a", true)], &[]),
        ],
    );
    assert_eq!((val(&io, "b"), val(&io, "c"), val(&io, "d")), (0.0, 1.0, 0.0));
    io.set_input(0, 1.0, 0.0).unwrap();
    let names: Vec<String> = log(&io).into_iter().map(|e| e.1).collect();
    assert_eq!(names, vec!["a", "b", "c"]);
    assert_eq!(val(&io, "d"), 0.0);
}

#[test]
fn an_order_to_a_result_holds_until_an_actor_changes() {
    let mut io = system(vec![sig("do7", DO), sig("do8", DO)], vec![cross("do8", &[("do7", false)], &[])]);
    io.set(id(&io, "do8"), 1.0, 0.0).unwrap();
    assert_eq!(val(&io, "do8"), 1.0);
    io.set(id(&io, "do7"), 1.0, 1.0).unwrap();
    io.set(id(&io, "do7"), 0.0, 2.0).unwrap();
    assert_eq!(val(&io, "do8"), 0.0);
}

#[test]
fn a_delay_is_not_copied_to_the_result() {
    // do2 = do1. A delayed order on do1 changes do2 only when do1 changes; an order to do2
    // meanwhile does not cancel do1's delayed change.
    let mut io = system(vec![sig("do1", DO), sig("do2", DO)], vec![cross("do2", &[("do1", false)], &[])]);
    io.set_delayed(id(&io, "do1"), 1.0, 0.0, 0.5).unwrap();
    io.set(id(&io, "do2"), 1.0, 0.1).unwrap();
    io.set(id(&io, "do2"), 0.0, 0.2).unwrap();
    io.advance(0.5);
    assert_eq!((val(&io, "do1"), val(&io, "do2")), (1.0, 1.0));
    let last = io.changes().last().cloned();
    assert_eq!(last.map(|c| (c.time, c.signal.to_string(), c.cause)), Some((0.5, "do2".to_string(), Cause::Cross)));
}
