//! Reading RAPID motion data values (speeddata, zonedata, tooldata, wobjdata,
//! robtarget, jointtarget) into the motion library's types, and making robtarget,
//! jointtarget, confdata and pos values from its results.

use crate::RobotResources;
use std::rc::Rc;

use nalgebra::Isometry3;
use rapid_motion::frames::FrameChain;
use rapid_motion::plan::{SpeedData, ZoneData};
use rapid_motion::Joints;

use super::frame;
use rapid_vm::ext::{Ctx, Err, RapidError, Record, Value};

/// External axis values at or above this mark an axis that is not used (9E9).
pub(super) const UNUSED_AXIS: f64 = 9e9;

fn record<'v>(ctx: &Ctx<'_>, value: &'v Value, n: usize, what: &str) -> Result<&'v [Value], RapidError> {
    match value {
        Value::Record(r) if r.fields.len() == n => Ok(&r.fields),
        _ => Err(ctx.error(Err::ArgValue, format!("{what} was expected"))),
    }
}

fn number(ctx: &Ctx<'_>, value: &Value, what: &str) -> Result<f64, RapidError> {
    value.as_f64().ok_or_else(|| ctx.error(Err::ArgValue, format!("{what}: a number was expected")))
}

fn boolean(ctx: &Ctx<'_>, value: &Value, what: &str) -> Result<bool, RapidError> {
    match value {
        Value::Bool(b) => Ok(*b),
        _ => Err(ctx.error(Err::ArgValue, format!("{what}: a bool was expected"))),
    }
}

/// `speeddata [v_tcp, v_ori, v_leax, v_reax]`.
pub(super) fn speed(ctx: &Ctx<'_>, value: &Value) -> Result<SpeedData, RapidError> {
    let f = record(ctx, value, 4, "a speeddata")?;
    Ok(SpeedData {
        v_tcp: number(ctx, &f[0], "speeddata")?,
        v_ori: number(ctx, &f[1], "speeddata")?,
        v_leax: number(ctx, &f[2], "speeddata")?,
        v_reax: number(ctx, &f[3], "speeddata")?,
    })
}

/// `zonedata [finep, pzone_tcp, pzone_ori, pzone_eax, zone_ori, zone_leax, zone_reax]`.
pub(super) fn zone(ctx: &Ctx<'_>, value: &Value) -> Result<ZoneData, RapidError> {
    let f = record(ctx, value, 7, "a zonedata")?;
    let n = |i: usize| number(ctx, &f[i], "zonedata");
    Ok(ZoneData {
        finep: boolean(ctx, &f[0], "zonedata")?,
        pzone_tcp: n(1)?,
        pzone_ori: n(2)?,
        pzone_eax: n(3)?,
        zone_ori: n(4)?,
        zone_leax: n(5)?,
        zone_reax: n(6)?,
    })
}

/// Whether the robot holds the tool (`tooldata`'s robhold; FALSE: a stationary tool).
pub(super) fn tool_held(ctx: &Ctx<'_>, tool: &Value) -> Result<bool, RapidError> {
    let t = record(ctx, tool, 3, "a tooldata")?;
    boolean(ctx, &t[0], "tooldata")
}

/// The frames of a tool (`tooldata [robhold, tframe, tload]`) and a work object
/// (`wobjdata [robhold, ufprog, ufmec, uframe, oframe]`; wobj0 when none), with the
/// program displacement. A moving work object (`ufprog` FALSE) rides the conveyor its
/// `ufmec` names: its user frame is where the connected object is now; any other
/// moving work object is refused.
pub(super) fn chain(
    ctx: &Ctx<'_>,
    tool: &Value,
    wobj: Option<&Value>,
    pdisp: Isometry3<f64>,
) -> Result<FrameChain, RapidError> {
    let t = record(ctx, tool, 3, "a tooldata")?;
    let tool_held = boolean(ctx, &t[0], "tooldata")?;
    let tframe = frame::frame(ctx, &t[1])?;
    // On a track the robot's base is where the track is now.
    let base = ctx.resources.robot().track_base_at(ctx.time);
    let mut chain = FrameChain { tframe, pdisp, base, ..FrameChain::default() };
    let Some(wobj) = wobj else { return Ok(chain) };
    let w = record(ctx, wobj, 5, "a wobjdata")?;
    let wobj_held = boolean(ctx, &w[0], "wobjdata")?;
    chain.uframe = match boolean(ctx, &w[1], "wobjdata")? {
        true => frame::frame(ctx, &w[3])?,
        false => conveyor_frame(ctx, wobj)?,
    };
    chain.oframe = frame::frame(ctx, &w[4])?;
    chain.stationary_tool = match (tool_held, wobj_held) {
        (true, false) => false,
        (false, true) => true,
        // uncertain: the controller's error for a tool and work object both held (or
        // both fixed) is not public; execution stops.
        _ => return Err(RapidError::fatal("the tool and the work object cannot both be held (or both fixed)")),
    };
    Ok(chain)
}

/// The user frame of a work object a mechanical unit moves, where it is now: a
/// conveyor's base frame moved by the connected object's distance from the sync switch,
/// or an external unit's frame carried by its axes.
fn conveyor_frame(ctx: &Ctx<'_>, wobj: &Value) -> Result<Isometry3<f64>, RapidError> {
    use super::tracking::Carrier;
    let robot = ctx.resources.robot();
    match super::tracking::carrier_of(ctx, wobj)? {
        Some(Carrier::Conveyor(c)) => {
            let conveyor = &robot.following.conveyors[c];
            match conveyor.distance(ctx.time) {
                Some(d) => Ok(conveyor.frame_at(d)),
                None => {
                    Err(ctx.error(Err::CnvNotActive, "the conveyor's work object is connected to no object (WaitWObj)"))
                }
            }
        }
        Some(Carrier::Unit(u)) => {
            let mover = super::tracking::unit_mover(robot, u)?;
            let at = robot.eax_at(ctx.time).unwrap_or_default();
            Ok(mover.user_frame(&robot.following.conveyors, &at))
        }
        Some(carrier @ Carrier::Foreign(f)) => {
            let mover = super::tracking::mover_of(ctx, carrier)?;
            let at = robot.foreign_eax_at(f, ctx.time).unwrap_or_default();
            Ok(mover.user_frame(&robot.following.conveyors, &at))
        }
        None => Err(RapidError::fatal(unfollowed_mover(ctx, super::tracking::ufmec(wobj).unwrap_or("")))),
    }
}

/// Why a work object moved by mechanical unit `name` (`ufmec`) cannot be followed.
fn unfollowed_mover(ctx: &Ctx<'_>, name: &str) -> String {
    if super::units::unit_named(ctx, name).is_some() {
        return format!(
            "a work object moved by the robot {name} (MultiMove coordinated movement) is not supported yet; \
             a robot's own held work object is robhold TRUE"
        );
    }
    format!(
        "the work object is moved by mechanical unit `{name}` (ufprog FALSE, ufmec), which is no conveyor or \
         external unit with a frame (base, orientation) of the system"
    )
}

/// A robtarget's pose (trans, rot) and configuration (cf1, cf4, cf6, cfx).
pub(super) fn robtarget(ctx: &Ctx<'_>, value: &Value) -> Result<(Isometry3<f64>, [i32; 4]), RapidError> {
    let f = record(ctx, value, 4, "a robtarget")?;
    let pose = frame::frame(ctx, value)?;
    let c = record(ctx, &f[2], 4, "a confdata")?;
    let mut conf = [0; 4];
    for (slot, field) in conf.iter_mut().zip(c) {
        *slot = number(ctx, field, "confdata")? as i32;
    }
    Ok((pose, conf))
}

/// A robtarget's or jointtarget's external axis values (`extax`, its last field).
pub(super) fn target_extax(ctx: &Ctx<'_>, target: &Value) -> Result<[f64; 6], RapidError> {
    match target {
        Value::Record(r) if matches!(r.fields.len(), 2 | 4) => {
            super::frame::extjoint(ctx, &r.fields[r.fields.len() - 1])
        }
        _ => Err(ctx.error(Err::ArgValue, "a robtarget or jointtarget was expected")),
    }
}

/// A jointtarget's robot axes.
pub(super) fn jointtarget(ctx: &Ctx<'_>, value: &Value) -> Result<Joints, RapidError> {
    let f = record(ctx, value, 2, "a jointtarget")?;
    let r = record(ctx, &f[0], 6, "a robjoint")?;
    let mut joints = [0.0; 6];
    for (slot, field) in joints.iter_mut().zip(r) {
        *slot = number(ctx, field, "robjoint")?;
    }
    Ok(joints)
}

/// A record of program type `name`.
fn make(ctx: &Ctx<'_>, name: &str, fields: Vec<Value>) -> Result<Value, RapidError> {
    let Some(ty) = rapid_vm::ext::type_named(ctx, name) else {
        return Err(RapidError::fatal(format!("the program has no type {name}")));
    };
    Ok(Value::Record(Rc::new(Record { ty, fields })))
}

fn nums(values: &[f64]) -> Vec<Value> {
    values.iter().map(|&x| Value::Num(if x == 0.0 { 0.0 } else { x as f32 })).collect()
}

/// `pos [x, y, z]`.
pub(super) fn pos_value(ctx: &Ctx<'_>, pose: &Isometry3<f64>) -> Result<Value, RapidError> {
    let t = pose.translation.vector;
    make(ctx, "pos", nums(&[t.x, t.y, t.z]))
}

/// `robtarget [trans, rot, robconf, extax]` with unused external axes; the orient
/// with q1 ≥ 0.
pub(super) fn robtarget_value(ctx: &Ctx<'_>, pose: &Isometry3<f64>, conf: [i32; 4]) -> Result<Value, RapidError> {
    let [q1, q2, q3, q4] = rapid_motion::pose::orient(pose);
    let rot = make(ctx, "orient", nums(&[q1, q2, q3, q4]))?;
    let robconf = make(ctx, "confdata", nums(&conf.map(f64::from)))?;
    let extax = make(ctx, "extjoint", nums(&[UNUSED_AXIS; 6]))?;
    make(ctx, "robtarget", vec![pos_value(ctx, pose)?, rot, robconf, extax])
}

/// `jointtarget [robax, extax]` with unused external axes.
pub(super) fn jointtarget_value(ctx: &Ctx<'_>, joints: &Joints) -> Result<Value, RapidError> {
    let robax = make(ctx, "robjoint", nums(joints))?;
    let extax = make(ctx, "extjoint", nums(&[UNUSED_AXIS; 6]))?;
    make(ctx, "jointtarget", vec![robax, extax])
}
