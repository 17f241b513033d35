//! TriggCheckIO, and the actions decided when the robot gets to their place (a check,
//! an output or interrupt with `\Inhib`): once the move is final their time is known;
//! they wait in [`super::TriggState::pending`] and the executor, woken at that time,
//! runs them through [`poll`] before it looks for interrupts.

use super::super::robot::{Action, PathEvent};
use super::{check_value, define, inhib_place, place, refuse, Relation, Res, Special};
use crate::RobotResources;
use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, Err, Place, Resources, Storage, Value};

rapid_vm::ext::layout! {
    static TRIGG_CHECK: CheckArgs = "TriggCheckIO" {
        data: "TriggData", distance: "Distance", start: "Start", next: "Next", time: "Time", signal: "Signal",
        relation: "Relation", value: "CheckValue", dvalue: "CheckDvalue", stop_move: "StopMove",
        interrupt: "Interrupt", inhib: "Inhib", mode: "Mode",
    }
}

/// `TriggCheckIO TriggData, Distance [\Start] | [\Time], Signal, Relation, CheckValue |
/// CheckDvalue [\StopMove], Interrupt [\Inhib]`: at the place the signal is compared
/// with the value; when the comparison fails the interrupt fires, and with
/// `\StopMove` the robot stops on its path (StartMove goes on).
pub(crate) fn trigg_check_io(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let ch = *TRIGG_CHECK;
    refuse(args, &[(ch.next, "\\Next"), (ch.mode, "\\Mode")])?;
    let at = place(ctx, args, (ch.distance, ch.start, ch.time))?;
    let data = ctx.value(&args[ch.signal])?;
    if !matches!(data, Value::Opaque(_)) {
        return Err(ctx.error(Err::ArgValue, "TriggCheckIO's Signal must be signal data (signaldi … signalgo)"));
    }
    let signal = rapid_signals::signal(ctx, &args[ch.signal])?;
    let relation = ctx.num(&args[ch.relation])?;
    let Some(relation) = Relation::from_opnum(relation) else {
        return Err(ctx.error(Err::ArgValue, format!("Relation {relation} is not an opnum (LT … GT)")));
    };
    let value = if present(args.get(ch.dvalue)) { ctx.num(&args[ch.dvalue])? } else { ctx.num(&args[ch.value])? };
    check_value(ctx, signal, value)?;
    let interrupt = rapid_vm::ext::interrupt_number(ctx, &args[ch.interrupt])?;
    let stop = present(args.get(ch.stop_move));
    let special = Special::Check { signal, relation, value, stop, interrupt, inhib: inhib_place(args, ch.inhib) };
    define(ctx, &args[ch.data], PathEvent { at, shift: 0.0, action: Action::Special(0) }, Some(special))
}

/// A deferred action's time is known: it waits for the executor, which a scheduled
/// interrupt of number 0 (no interrupt has it, so none fires) wakes at that time.
pub(crate) fn defer(ctx: &mut Ctx<'_>, time: f64, key: u32) {
    let Some(special) = ctx.resources.robot_mut().trigg.live.remove(&key) else { return };
    ctx.resources.robot_mut().trigg.pending.push((time, special));
    ctx.resources.interrupts.schedule(time, 0);
}

/// Runs the deferred actions due by `now` (not those after a StopMove's stop: they
/// come later by the time the robot stood).
pub(crate) fn poll(resources: &mut Resources, storage: &Storage, now: f64) {
    if resources.robot_mut().trigg.pending.is_empty() {
        return;
    }
    let held_after = resources.robot_mut().pause.as_ref().map_or(f64::INFINITY, |p| p.since);
    let mut due = Vec::new();
    resources.robot_mut().trigg.pending.retain(|(t, special)| {
        let ready = *t <= now && *t <= held_after;
        if ready {
            due.push((*t, special.clone()));
        }
        !ready
    });
    due.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (_, special) in due {
        act(resources, storage, now, special);
    }
}

/// Whether an `\Inhib` flag is TRUE now.
fn inhibited(storage: &Storage, flag: Option<&Place>) -> bool {
    flag.is_some_and(|p| matches!(storage.get(p), Ok(Value::Bool(true))))
}

/// A deferred action at the robot's place, now.
// uncertain: the signal is read when the executor wakes, within the 4 ms path
// resolution of the place; a signal on a stopped device fails no check (the
// controller reports the device itself).
fn act(resources: &mut Resources, storage: &Storage, now: f64, special: Special) {
    match special {
        Special::Check { signal, relation, value, stop, interrupt, inhib } => {
            if inhibited(storage, inhib.as_ref()) {
                return;
            }
            resources.io_mut().advance(now);
            let Some(actual) = resources.io().system.as_ref().and_then(|io| io.read(signal).ok()) else { return };
            if relation.holds(actual, value) {
                return;
            }
            resources.interrupts.fire(interrupt);
            if stop {
                super::super::pause::hold(resources, now);
            }
        }
        Special::Inhibited { signal, value, inhib, inhib_value } => {
            let value = if inhibited(storage, Some(&inhib)) { inhib_value } else { value };
            resources.io_mut().advance(now);
            if let Some(io) = resources.io_mut().system.as_mut() {
                let _ = io.set(signal, value, now);
            }
        }
        Special::InhibitedInterrupt { interrupt, inhib } => {
            if !inhibited(storage, Some(&inhib)) {
                resources.interrupts.fire(interrupt);
            }
        }
        Special::Ramp { .. } | Special::Speed { .. } => {}
    }
}
