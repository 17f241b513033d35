//! TriggL, TriggJ, TriggC and TriggAbsJ: moves that fire the triggers they name
//! (Trigg_1 or every element of TriggArray, and T2 … T8).

use crate::RobotResources;
use rapid_vm::ext::{present, Ctx, Err, OpaqueState, RapidError, Value};
use std::sync::LazyLock;

use super::super::moves::{abs_joint_move, circular_move, joint_move, linear_move, Layout};
use super::super::robot::{Action, PathEvent};
use super::{value_after_orders, Res, Special};

/// The trigger handles of the triggdata arguments: Trigg_1 up to Zone (Trigg_1,
/// TriggArray, T2 … T8).
fn handles(ctx: &Ctx<'_>, args: &[Value], layout: &Layout) -> Result<Vec<usize>, RapidError> {
    let mut handles = Vec::new();
    let mut add = |value: &Value| {
        if let Value::Opaque(o) = value {
            if let OpaqueState::Handle(h) = o.state {
                handles.push(h as usize);
            }
        }
    };
    for idx in layout.trigg..layout.zone {
        if !present(args.get(idx)) {
            continue;
        }
        match ctx.value(&args[idx])? {
            Value::Array(array) => array.elems.iter().for_each(&mut add),
            value => add(&value),
        }
    }
    Ok(handles)
}

/// The events of the triggers a move names; the move takes its own copy of each
/// special definition (a ramp's start value resolved now). A TriggSpeed whose value
/// at the programmed speed exceeds its output's limit is ERR_AO_LIM.
fn triggers_of(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout) -> Result<Vec<PathEvent>, RapidError> {
    let speed = layout.speed;
    let mut events = Vec::new();
    for h in handles(ctx, args, layout)? {
        let Some(&event) = ctx.resources.robot_mut().triggers.get(h) else {
            return Err(ctx.error(Err::ArgValue, "a triggdata was never defined (TriggIO)"));
        };
        let Some(special) = ctx.resources.robot_mut().trigg.def(h).cloned() else {
            events.push(event);
            continue;
        };
        let special = match special {
            Special::Ramp { signal, to, length, by_time, lag, .. } => {
                Special::Ramp { signal, from: value_after_orders(ctx, signal), to, length, by_time, lag }
            }
            Special::Speed { scale, max: Some(max), .. } => {
                let v = super::super::data::speed(ctx, &ctx.value(&args[speed])?)?.v_tcp;
                if scale * v > max {
                    return Err(ctx.error(
                        Err::AoLim,
                        format!("TriggSpeed: {scale} × {v} mm/s is above the analog output's limit {max}"),
                    ));
                }
                special
            }
            other => other,
        };
        let key = ctx.resources.robot_mut().trigg.take_copy(special);
        events.push(PathEvent { action: Action::Special(key), ..event });
    }
    Ok(events)
}

static TRIGG_L: LazyLock<Layout> = LazyLock::new(|| Layout::of("TriggL"));
static TRIGG_J: LazyLock<Layout> = LazyLock::new(|| Layout::of("TriggJ"));
static TRIGG_C: LazyLock<Layout> = LazyLock::new(|| Layout::of("TriggC"));
static TRIGG_ABS_J: LazyLock<Layout> = LazyLock::new(|| Layout::of("TriggAbsJ"));

/// `TriggL`: MoveL firing its triggers.
pub(crate) fn trigg_l(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = triggers_of(ctx, args, &TRIGG_L)?;
    linear_move(ctx, args, &TRIGG_L, events)
}

/// `TriggJ`: MoveJ firing its triggers.
pub(crate) fn trigg_j(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = triggers_of(ctx, args, &TRIGG_J)?;
    joint_move(ctx, args, &TRIGG_J, events)
}

/// `TriggC`: MoveC firing its triggers.
pub(crate) fn trigg_c(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = triggers_of(ctx, args, &TRIGG_C)?;
    circular_move(ctx, args, &TRIGG_C, events)
}

/// `TriggAbsJ`: MoveAbsJ firing its triggers.
pub(crate) fn trigg_abs_j(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = triggers_of(ctx, args, &TRIGG_ABS_J)?;
    abs_joint_move(ctx, args, &TRIGG_ABS_J, events)
}

/// The layouts of TriggLIOs and TriggJIOs (for `ios.rs`).
pub(super) static TRIGG_L_IOS: LazyLock<Layout> = LazyLock::new(|| Layout::of("TriggLIOs"));
pub(super) static TRIGG_J_IOS: LazyLock<Layout> = LazyLock::new(|| Layout::of("TriggJIOs"));
