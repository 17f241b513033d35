//! Axis torques and load identification (§1.8): GetMotorTorque, from the load model of
//! `rapid_motion::dynamics`: the torque each axis needs to hold the tool's load and
//! the payload against gravity and to accelerate them as the robot moves them now.
//!
//! Not modelled (not public, or not simulated): the arm's own link masses, friction,
//! the loads' rotational inertia, and the gear ratios (a ratio of 1 is used, so a motor
//! torque is the axis torque). GetTorqueMargin and ResetTorqueMargin need the motors' torque
//! limits, which are not public either; they stay unregistered. ParIdRobValid tells
//! which identifications the robot allows.

use crate::RobotResources;
use nalgebra::{Point3, Vector3};
use rapid_motion::dynamics::{moving_torques, PointLoad};

use super::frame;
use super::units::{axis_arg, opt_unit_arg, own_only, ROBOT_AXES};
use rapid_vm::ext::{Ctx, Err, Place, RapidError, Root, Value};

type Res = Result<Option<Value>, RapidError>;

/// The active tool's value: the one the last move or SetSysData made active, else
/// tool0.
fn active_tool(ctx: &Ctx<'_>) -> Option<Value> {
    let place = match &ctx.resources.motion().active[0] {
        Some((_, place)) => place.clone(),
        None => Place { root: Root::Global(ctx.resources.motion().links.sysdata[0]?), path: Vec::new() },
    };
    ctx.storage.get(&place).ok().cloned()
}

/// A loaddata's mass and centre of gravity.
fn mass_cog(ctx: &Ctx<'_>, load: &Value) -> Option<(f64, Vector3<f64>)> {
    let Value::Record(record) = load else { return None };
    let mass = record.fields.first()?.as_f64()?;
    let cog = frame::vector(ctx, record.fields.get(1)?).ok()?;
    Some((mass, cog))
}

/// The loads on the flange: the active tool's `tload` (its centre of gravity is in
/// the flange frame) and the GripLoad payload (in the tool frame of a robot-held
/// tool).
// uncertain: with a stationary tool the payload's centre of gravity is taken to be
// in the flange frame, as the gripper holding the work object is the robot's.
fn loads(ctx: &Ctx<'_>) -> Vec<PointLoad> {
    let mut loads = Vec::with_capacity(2);
    let tool = active_tool(ctx);
    let mut tframe = nalgebra::Isometry3::identity();
    if let Some(Value::Record(tool)) = &tool {
        let held = matches!(tool.fields.first(), Some(Value::Bool(true)));
        if held {
            if let Some(f) = tool.fields.get(1).and_then(|f| frame::frame(ctx, f).ok()) {
                tframe = f;
            }
        }
        if let Some((mass, cog)) = tool.fields.get(2).and_then(|l| mass_cog(ctx, l)) {
            loads.push(PointLoad { mass, cog });
        }
    }
    let payload = &ctx.resources.motion().settings.grip_load;
    let cog = tframe * Point3::new(payload.cog[0], payload.cog[1], payload.cog[2]);
    loads.push(PointLoad { mass: payload.mass, cog: cog.coords });
    loads
}

/// The half width of the second difference that gives the loads' acceleration, s.
const ACCEL_H: f64 = 0.002;

/// The torque of each axis now, Nm: holding the loads and accelerating them.
pub(super) fn axis_torques(ctx: &mut Ctx<'_>) -> [f64; ROBOT_AXES] {
    let loads = loads(ctx);
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    let joints = [robot.joints_at((now - ACCEL_H).max(0.0)), robot.joints_at(now), robot.joints_at(now + ACCEL_H)];
    moving_torques(&robot.kin, &joints, ACCEL_H, &loads)
}

/// `GetMotorTorque([\MecUnit,] AxisNo)`: the motor torque of an axis now, Nm: the
/// torque that holds the tool load and the payload against gravity and accelerates them.
// uncertain: which units and sign the controller reports are not public; ours is the
// torque the motor gives, positive in the axis's positive direction.
pub(crate) fn get_motor_torque(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let unit = opt_unit_arg(ctx, args, 0)?;
    own_only(ctx, unit)?;
    let axis = axis_arg(ctx, ctx.num(&args[1])?, Err::ArgValue)?;
    let torques = axis_torques(ctx);
    Ok(Some(Value::Num(torques[axis - 1] as f32)))
}

// The paridnum and paridvalidnum values of the catalogue.
const TOOL_LOAD_ID: f64 = 1.0;
const PAY_LOAD_ID: f64 = 2.0;
const IRBP_FIRST: f64 = 3.0;
const IRBP_LAST: f64 = 6.0;
const ROB_LOAD_VAL: f32 = 1.0;
const ROB_NOT_LOAD_VAL: f32 = 10.0;

/// `ParIdRobValid(ParIdType [\MechUnit] [\AxisNo])`: whether the unit's type allows
/// the identification: tool and payload identification on a TCP robot are valid
/// (ROB_LOAD_VAL); the positioner kinds (IRBP_*) are not, since every unit here is a
/// TCP robot (ROB_NOT_LOAD_VAL). Another ParIdType is ERR_ARGVALERR.
// uncertain: every built-in robot model is taken to support load identification (the
// list of models that do not, or only with a limited mass, is not public to us).
pub(crate) fn par_id_rob_valid(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let kind = ctx.num(&args[0])?;
    opt_unit_arg(ctx, args, 1)?;
    if let Some(axis) = ctx.opt_num(args.get(2))? {
        axis_arg(ctx, axis, Err::ArgValue)?;
    }
    let valid = if kind == TOOL_LOAD_ID || kind == PAY_LOAD_ID {
        ROB_LOAD_VAL
    } else if (IRBP_FIRST..=IRBP_LAST).contains(&kind) && kind.fract() == 0.0 {
        ROB_NOT_LOAD_VAL
    } else {
        return Err(ctx.error(Err::ArgValue, format!("{kind} is not a paridnum")));
    };
    Ok(Some(Value::Num(valid)))
}
