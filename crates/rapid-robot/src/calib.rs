//! Calibration instructions and functions (§1.18): MToolTCPCalib, MToolRotCalib,
//! SToolTCPCalib, SToolRotCalib, CalcRotAxisFrame, CalcRotAxFrameZ. The fits are
//! `rapid_motion::calib`'s; this file reads the taught positions and writes the
//! results into the tool and the error outputs.
//!
//! Jointtargets (the M… instructions) become flange poses through the robot's
//! forward kinematics; robtargets (the S… instructions, the axis frames) are taken as
//! they are, as positions in the world (wobj0) frame.

use crate::RobotResources;
use nalgebra::{Isometry3, Quaternion, Vector3};
use rapid_motion::calib::{moving_tool_rotation, rotation_axis_fit, stationary_tool_frame, tcp_fit, AxisFit};
use rapid_motion::{Kinematics, MotionError, Pose};

use super::units::unit_arg;
use super::{data, frame};
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// The fewest and most targets CalcRotAxisFrame and CalcRotAxFrameZ take.
// uncertain: at least 4 is the manual's minimum as we read it; the most, 100, is
// ours (a bound on the work).
const MIN_TARGETS: f64 = 4.0;
const MAX_TARGETS: f64 = 100.0;

rapid_vm::ext::layout! {
    static TCP_CALIB: TcpCalibArgs = "MToolTCPCalib" | "SToolTCPCalib" {
        tool: "Tool", max_err: "MaxErr", mean_err: "MeanErr",
    }
    static ROT_CALIB: RotCalibArgs = "MToolRotCalib" | "SToolRotCalib" { x_pos: "XPos", tool: "Tool" }
    static AXIS_FRAME: AxisFrameArgs = "CalcRotAxisFrame" {
        list: "TargetList", count: "TargetsInList", max_err: "MaxErr", mean_err: "MeanErr",
    }
    static AXIS_FRAME_Z: AxisFrameZArgs = "CalcRotAxFrameZ" {
        list: "TargetList", count: "TargetsInList", positive: "PositiveZPoint", max_err: "MaxErr", mean_err: "MeanErr",
    }
}

/// A tool calibration that cannot be done stops execution: the manual names no
/// error to catch.
// uncertain: the controller's reaction to unsuitable approach positions (an event
// log message and a stop) is assumed; no ERR_ constant is documented for them.
fn calib_failed(what: &str, why: &MotionError) -> RapidError {
    RapidError::fatal(format!("{what}: the positions do not suit a calibration: {why}"))
}

/// The flange poses of jointtarget arguments.
fn flange_poses(ctx: &Ctx<'_>, args: &[Value]) -> Result<Vec<Pose>, RapidError> {
    let kin = &ctx.resources.robot().kin;
    args.iter().map(|arg| Ok(kin.forward(&data::jointtarget(ctx, &ctx.value(arg)?)?))).collect()
}

/// The poses of robtarget arguments.
fn target_poses(ctx: &Ctx<'_>, args: &[Value]) -> Result<Vec<Pose>, RapidError> {
    args.iter().map(|arg| Ok(data::robtarget(ctx, &ctx.value(arg)?)?.0)).collect()
}

/// The tool argument's value and whether it is robot-held; `want_held` says which
/// kind the instruction calibrates (ERR_ARGVALERR for the other).
// uncertain: the manual requires a robot-held tool for the M… and a stationary one
// for the S… instructions; the error for the wrong kind is ours.
fn tool_of(ctx: &Ctx<'_>, arg: &Value, want_held: bool) -> Result<Value, RapidError> {
    let tool = ctx.value(arg)?;
    let held = match &tool {
        Value::Record(r) => matches!(r.fields.first(), Some(Value::Bool(true))),
        _ => return Err(ctx.error(Err::ArgValue, "a tooldata was expected")),
    };
    if held != want_held {
        let kind = if want_held { "robot-held (robhold TRUE)" } else { "stationary (robhold FALSE)" };
        return Err(ctx.error(Err::ArgValue, format!("the tool must be {kind}")));
    }
    Ok(tool)
}

/// The tool with a new tframe (translation and rotation), written back.
fn store_tframe(ctx: &mut Ctx<'_>, arg: &Value, tool: &Value, t: &Vector3<f64>, q: &Quaternion<f64>) -> Res {
    let Value::Record(record) = tool else { return Err(ctx.error(Err::ArgValue, "a tooldata was expected")) };
    let mut record = record.clone();
    if let Some(tframe) = std::rc::Rc::make_mut(&mut record).fields.get_mut(1) {
        *tframe = frame::with_trans_rot(tframe, t, &positive(q));
    }
    ctx.store(arg, Value::Record(record))?;
    Ok(None)
}

/// A quaternion written with q1 >= 0, as the controller shows orientations.
fn positive(q: &Quaternion<f64>) -> Quaternion<f64> {
    if q.w < 0.0 {
        -q
    } else {
        *q
    }
}

/// The tframe of a tool value.
fn tframe_of(ctx: &Ctx<'_>, tool: &Value) -> Result<Isometry3<f64>, RapidError> {
    match tool {
        Value::Record(r) if r.fields.len() >= 2 => frame::frame(ctx, &r.fields[1]),
        _ => Err(ctx.error(Err::ArgValue, "a tooldata was expected")),
    }
}

fn store_errors(ctx: &mut Ctx<'_>, max: &Value, mean: &Value, errs: (f64, f64)) -> Result<(), RapidError> {
    ctx.store(max, Value::Num(errs.0 as f32))?;
    ctx.store(mean, Value::Num(errs.1 as f32))
}

/// `MToolTCPCalib Pos1, Pos2, Pos3, Pos4, Tool, MaxErr, MeanErr`: the TCP of a
/// robot-held tool from four jointtargets where it touched one fixed point; its
/// orientation is kept.
pub(crate) fn m_tool_tcp_calib(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *TCP_CALIB;
    let poses = flange_poses(ctx, &args[..4])?;
    let tool = tool_of(ctx, &args[at.tool], true)?;
    let fit = tcp_fit(&poses).map_err(|e| calib_failed("MToolTCPCalib", &e))?;
    let q = tframe_of(ctx, &tool)?.rotation.into_inner();
    store_tframe(ctx, &args[at.tool], &tool, &fit.tcp, &q)?;
    store_errors(ctx, &args[at.max_err], &args[at.mean_err], (fit.max_err, fit.mean_err))?;
    Ok(None)
}

/// `MToolRotCalib RefTip, ZPos [\XPos], Tool`: the orientation of a robot-held tool
/// whose TCP is calibrated, from the fixed tip touched at RefTip and seen on the
/// tool's z axis (ZPos) and x axis (XPos).
pub(crate) fn m_tool_rot_calib(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ROT_CALIB;
    let ref_tip = flange_poses(ctx, &args[..1])?[0];
    let z_pos = flange_poses(ctx, &args[1..2])?[0];
    let x_pos = match args.get(at.x_pos).filter(|a| present(Some(a))) {
        Some(arg) => Some(flange_poses(ctx, std::slice::from_ref(arg))?[0]),
        None => None,
    };
    let tool = tool_of(ctx, &args[at.tool], true)?;
    let tcp = tframe_of(ctx, &tool)?.translation.vector;
    let rotation =
        moving_tool_rotation(&tcp, &ref_tip, &z_pos, x_pos.as_ref()).map_err(|e| calib_failed("MToolRotCalib", &e))?;
    store_tframe(ctx, &args[at.tool], &tool, &tcp, &rotation.into_inner())
}

/// `SToolTCPCalib Pos1, Pos2, Pos3, Pos4, Tool, MaxErr, MeanErr`: the TCP of a
/// stationary tool (in the world frame) from four robtargets where the robot's
/// pointer touched it in different orientations.
// uncertain: the robtargets are taken as poses of the pointer as it was taught; the
// fit finds the point the poses share, whether they were taught with tool0 or with a
// calibrated pointer.
pub(crate) fn s_tool_tcp_calib(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *TCP_CALIB;
    let poses = target_poses(ctx, &args[..4])?;
    let tool = tool_of(ctx, &args[at.tool], false)?;
    let fit = tcp_fit(&poses).map_err(|e| calib_failed("SToolTCPCalib", &e))?;
    let q = tframe_of(ctx, &tool)?.rotation.into_inner();
    store_tframe(ctx, &args[at.tool], &tool, &fit.point, &q)?;
    store_errors(ctx, &args[at.max_err], &args[at.mean_err], (fit.max_err, fit.mean_err))?;
    Ok(None)
}

/// `SToolRotCalib RefTip, ZPos, XPos, Tool`: the TCP and orientation of a stationary
/// tool from the pointer at its TCP, on its z axis and on its x axis.
pub(crate) fn s_tool_rot_calib(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ROT_CALIB;
    let p = target_poses(ctx, &args[..3])?;
    let tool = tool_of(ctx, &args[at.tool], false)?;
    let [tip, z, x] = [0, 1, 2].map(|i| p[i].translation.vector);
    let f = stationary_tool_frame(&tip, &z, &x).map_err(|e| calib_failed("SToolRotCalib", &e))?;
    store_tframe(ctx, &args[at.tool], &tool, &f.translation.vector, &f.rotation.into_inner())
}

/// The first `TargetsInList` points of a robtarget array (4..100 of them).
// uncertain: a count that is not a whole number in 4..100, or larger than the list,
// raises ERR_ARGVALERR.
fn axis_points(ctx: &Ctx<'_>, list: &Value, count: &Value) -> Result<Vec<Vector3<f64>>, RapidError> {
    let n = ctx.num(count)?;
    if n.fract() != 0.0 || !(MIN_TARGETS..=MAX_TARGETS).contains(&n) {
        return Err(ctx.error(Err::ArgValue, "TargetsInList must be a whole number from 4 to 100"));
    }
    let Value::Array(array) = ctx.value(list)? else {
        return Err(ctx.error(Err::ArgValue, "an array of robtargets was expected"));
    };
    let n = n as usize;
    if array.elems.len() < n {
        return Err(ctx.error(Err::ArgValue, "TargetsInList is larger than the target list"));
    }
    array.elems[..n].iter().map(|t| Ok(frame::trans_rot(ctx, t)?.0)).collect()
}

/// The frame of a fitted axis as a pose value, with the errors written out.
fn axis_result(ctx: &mut Ctx<'_>, fit: Result<AxisFit, MotionError>, max: &Value, mean: &Value) -> Res {
    let fit = fit.map_err(|e| ctx.error(Err::Frame, format!("no axis frame can be calculated: {e}")))?;
    store_errors(ctx, max, mean, (fit.max_err, fit.mean_err))?;
    Ok(Some(frame::pose_value(ctx, &fit.frame)?))
}

/// `CalcRotAxisFrame(MechUnit [\AxisNo], TargetList, TargetsInList, MaxErr,
/// MeanErr)`: the frame of a rotating axis from TCP positions taught at different
/// angles of it: the origin at the centre of their circle, z along the axis (the
/// targets in list order turn positively about it), x towards the first target.
/// Positions that fit no circle (coincident, on a line) are ERR_FRAME.
// uncertain: the system has no external axes; the unit is only checked to exist and
// the axis is taken from the targets alone.
pub(crate) fn calc_rot_axis_frame(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *AXIS_FRAME;
    unit_arg(ctx, args, 0)?;
    let points = axis_points(ctx, &args[at.list], &args[at.count])?;
    axis_result(ctx, rotation_axis_fit(&points, None), &args[at.max_err], &args[at.mean_err])
}

/// `CalcRotAxFrameZ(TargetList, TargetsInList, PositiveZPoint, MaxErr, MeanErr)`:
/// as CalcRotAxisFrame, with z turned to the side of PositiveZPoint.
pub(crate) fn calc_rot_ax_frame_z(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *AXIS_FRAME_Z;
    let points = axis_points(ctx, &args[at.list], &args[at.count])?;
    let positive = frame::trans_rot(ctx, &ctx.value(&args[at.positive])?)?.0;
    axis_result(ctx, rotation_axis_fit(&points, Some(&positive)), &args[at.max_err], &args[at.mean_err])
}
