//! Triggers on the path (§1.8). Definitions say what happens where: TriggIO,
//! TriggEquip and TriggInt (an output set, an interrupt fired), TriggCheckIO (a signal
//! checked), TriggRampAO (an analog output ramped), TriggSpeed (an analog output
//! following the TCP speed), at a distance before the move's point, after its start,
//! or a time before it. TriggL, TriggJ, TriggC and TriggAbsJ are moves that fire up to
//! eight of them; TriggLIOs and TriggJIOs fire the outputs of triggios arrays.
//! TriggDataCopy, TriggDataReset and TriggDataValid handle triggdata; TriggStopProc
//! supervises program stops.
//!
//! A triggdata holds the index of its definition in the robot's trigger table; the
//! definitions that are more than one action at one time live in [`TriggState`].

mod check;
mod data;
mod define;
mod ios;
mod moves;
mod path;
mod process;
mod state;
mod stopproc;

pub(crate) use check::{defer, poll, trigg_check_io};
pub(crate) use data::{trigg_data_copy, trigg_data_reset, trigg_data_valid};
pub(crate) use define::{trigg_equip, trigg_int, trigg_io};
pub(crate) use ios::{trigg_j_ios, trigg_l_ios};
pub(crate) use moves::{trigg_abs_j, trigg_c, trigg_j, trigg_l};
pub(crate) use process::{trigg_ramp_ao, trigg_speed};
pub(crate) use state::{Relation, Special, TriggState};
pub(crate) use stopproc::{program_stopped, trigg_stop_proc};

use super::robot::{At, PathEvent};
use crate::RobotResources;
use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, Err, Opaque, OpaqueState, Place, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// Options of the trigger definitions not modelled: execution stops, naming them.
fn refuse(args: &[Value], options: &[(usize, &str)]) -> Result<(), RapidError> {
    for &(idx, name) in options {
        if present(args.get(idx)) {
            return Err(RapidError::fatal(format!("{name} on a trigger is not supported by `rapid run` yet")));
        }
    }
    Ok(())
}

/// Where the trigger is: Distance mm before the point, after the start (`\Start`), or
/// seconds before the point (`\Time`); the arguments' positions (`time` is
/// `signature::ABSENT` for a trigger without `\Time`).
fn place(ctx: &Ctx<'_>, args: &[Value], (distance, start, time): (usize, usize, usize)) -> Result<At, RapidError> {
    let distance = ctx.num(&args[distance])?;
    if !distance.is_finite() || distance < 0.0 {
        return Err(ctx.error(Err::ArgValue, "a trigger's Distance must be 0 or more"));
    }
    Ok(if present(args.get(start)) {
        At::AfterStart(distance)
    } else if present(args.get(time)) {
        At::SecondsBefore(distance)
    } else {
        At::BeforePoint(distance)
    })
}

/// The persistent an `\Inhib` argument names.
fn inhib_place(args: &[Value], idx: usize) -> Option<Place> {
    match args.get(idx) {
        Some(Value::Ref(place)) => Some((**place).clone()),
        _ => None,
    }
}

/// Stores a trigger definition in its triggdata (reusing its slot when it has one);
/// `special` is its action when that is more than one output or interrupt.
fn define(ctx: &mut Ctx<'_>, arg: &Value, event: PathEvent, special: Option<Special>) -> Res {
    let (opaque, handle) = ctx.handle_arg(arg, "a triggdata")?;
    let robot = ctx.resources.robot_mut();
    let index = match handle.map(|h| h as usize).filter(|&h| h < robot.triggers.len()) {
        Some(h) => {
            robot.triggers[h] = event;
            h
        }
        None => {
            robot.triggers.push(event);
            robot.triggers.len() - 1
        }
    };
    robot.trigg.set_def(index, special);
    let data = Opaque { ty: opaque.ty, state: OpaqueState::Handle(index as u32) };
    ctx.store(arg, Value::Opaque(Box::new(data)))?;
    Ok(None)
}

/// A value an output (or a checked signal) may take: within an analog signal's
/// logical range (ERR_AO_LIM), a group's bits (ERR_GO_LIM).
fn check_value(ctx: &Ctx<'_>, id: u32, value: f64) -> Result<(), RapidError> {
    let Some(def) = ctx.resources.io().system.as_ref().and_then(|io| io.def(id)) else { return Ok(()) };
    if def.kind.is_analog() {
        let out = def.analog.is_some_and(|r| value < r.logical_min || value > r.logical_max);
        if out || !value.is_finite() {
            return Err(ctx.error(Err::AoLim, format!("{value} is outside the limits of analog signal {}", def.name)));
        }
    } else if def.kind.is_group() {
        let max = rapid_io::group_max(def.group_bits);
        if !(0.0..=max).contains(&value) || value.fract() != 0.0 {
            return Err(ctx.error(Err::GoLim, format!("{value} is outside the range of group signal {}", def.name)));
        }
    }
    Ok(())
}

/// The logical maximum of an analog signal (None: not analog, or unbounded).
fn analog_max(ctx: &Ctx<'_>, id: u32) -> Option<f64> {
    let def = ctx.resources.io().system.as_ref().and_then(|io| io.def(id))?;
    def.analog.map(|r| r.logical_max)
}

/// The value output `id` will have once the outputs already ordered on the path are
/// set (a ramp starts from it).
fn value_after_orders(ctx: &Ctx<'_>, id: u32) -> f64 {
    let io = ctx.resources.io();
    let ordered = io.path_orders.iter().rev().find(|&&(_, s, _)| s == id).map(|&(_, _, v)| v);
    ordered.or_else(|| io.system.as_ref().and_then(|s| s.value(id))).unwrap_or(0.0)
}
