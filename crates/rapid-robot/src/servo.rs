//! Servo and supervision settings (§1.7, §1.8): MotionSup, SoftAct, SoftDeact,
//! TuneServo, TuneReset, ActEventBuffer, DeactEventBuffer, SpeedLimAxis,
//! SpeedLimCheckPoint, PFRestart.
//!
//! What is modelled: the state each instruction sets, its checks and errors, and its
//! reset at PP to Main. What is not: the physics behind them. The simulated robot
//! follows its planned path exactly, so servo softness and tuning change nothing it
//! does; there are no collisions for motion supervision to detect; the configured
//! event preset time is 0, so the event buffer moves no event; and the speed limits
//! of SpeedLimAxis and SpeedLimCheckPoint act only while the system input
//! LimitSpeed is set, which a `rapid run` system does not have.

use super::units::{axis_arg, opt_unit_arg, own_only, unit_arg, ROBOT_AXES};
use crate::RobotResources;
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// The tunetype values TUNE_DF (0) … TUNE_DL (10) of the catalogue.
const TUNE_TYPES: usize = 11;

/// The servo and supervision state of the task's robot.
#[derive(Debug, Clone, PartialEq)]
pub struct ServoState {
    /// MotionSup: collision supervision on, and its level in percent (C_MOTSET
    /// motionsup, tunevalue).
    pub motion_sup: bool,
    pub sup_level: f64,
    /// SoftAct: softness and ramp (percent) of each soft axis.
    pub soft: [Option<(f64, f64)>; ROBOT_AXES],
    /// TuneServo: each axis's tuning in percent, by tunetype.
    pub tune: [[f64; TUNE_TYPES]; ROBOT_AXES],
    /// ActEventBuffer / DeactEventBuffer (C_MOTSET evtbufferact).
    pub event_buffer: bool,
    /// SpeedLimAxis: each axis's limit (deg/s) while LimitSpeed is set.
    pub axis_speed_limit: [Option<f64>; ROBOT_AXES],
    /// SpeedLimCheckPoint: the check points' limit (mm/s) while LimitSpeed is set.
    pub check_point_limit: Option<f64>,
    /// TestSignDefine: the signal on each channel.
    pub test_signals: [Option<super::testsign::TestSignal>; super::testsign::CHANNELS],
}

impl Default for ServoState {
    /// Supervision on at 100 %, no soft axes, every tuning 100 %, the event buffer
    /// on, no speed limits, no test signals. The first three match C_MOTSET's
    /// initial motionsup TRUE, tunevalue 100, evtbufferact TRUE.
    fn default() -> ServoState {
        ServoState {
            motion_sup: true,
            sup_level: 100.0,
            soft: [None; ROBOT_AXES],
            tune: [[100.0; TUNE_TYPES]; ROBOT_AXES],
            event_buffer: true,
            axis_speed_limit: [None; ROBOT_AXES],
            check_point_limit: None,
            test_signals: Default::default(),
        }
    }
}

fn servo<'c>(ctx: &'c mut Ctx<'_>) -> &'c mut ServoState {
    &mut ctx.resources.motion_mut().servo
}

/// Writes the settings C_MOTSET shows (motionsup, tunevalue, evtbufferact) into it.
fn mirror(ctx: &mut Ctx<'_>) {
    let s = &ctx.resources.motion_mut().servo;
    let leaves =
        [(&[5][..], Value::Bool(s.motion_sup)), (&[6], super::num(s.sup_level)), (&[14], Value::Bool(s.event_buffer))];
    if let Some(global) = ctx.resources.motion_mut().links.motset {
        super::write_leaves(ctx.storage.globals.get_mut(global), &leaves);
    }
}

/// A percentage argument within `lo..=hi`, else ERR_ARGVALERR.
fn percent(ctx: &Ctx<'_>, value: f64, lo: f64, hi: f64, what: &str) -> Result<f64, RapidError> {
    if (lo..=hi).contains(&value) {
        return Ok(value);
    }
    Err(ctx.error(Err::ArgValue, format!("{what} {value} is outside {lo}..{hi} %")))
}

/// `MotionSup [\On] | [\Off] [\TuneValue] [\NoBackoff]`: collision supervision on
/// (the default, also with no switch) or off; `\TuneValue` sets its level, 1..300 %
/// of the configured one.
// uncertain: a TuneValue outside 1..300 raises ERR_ARGVALERR (the manual gives the
// range, not the reaction); \TuneValue with \Off changes nothing.
pub(crate) fn motion_sup(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let off = present(args.get(1));
    let level = match ctx.opt_num(args.get(2))? {
        Some(v) => Some(percent(ctx, v, 1.0, 300.0, "MotionSup TuneValue")?),
        None => None,
    };
    let state = servo(ctx);
    state.motion_sup = !off;
    if let (false, Some(level)) = (off, level) {
        state.sup_level = level;
    } else if !off {
        state.sup_level = 100.0;
    }
    mirror(ctx);
    Ok(None)
}

rapid_vm::ext::layout! {
    static SOFT_ACT: SoftActArgs = "SoftAct" { axis: "Axis", softness: "Softness", ramp: "Ramp" }
    static TUNE_SERVO: TuneServoArgs = "TuneServo" { axis: "Axis", tune_value: "TuneValue", ty: "Type" }
    static SPEED_LIM_AXIS: SpeedLimAxisArgs = "SpeedLimAxis" { axis_no: "AxisNo", axis_speed: "AxisSpeed" }
}

/// `SoftAct [\MechUnit,] Axis, Softness [\Ramp]`: the axis becomes soft, Softness
/// 0 (stiffest soft servo) .. 100 % (softest); Ramp, at least 100 %, slows the change.
// uncertain: Softness outside 0..100 or a Ramp below 100 raises ERR_ARGVALERR.
pub(crate) fn soft_act(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SOFT_ACT;
    let unit = opt_unit_arg(ctx, args, 0)?;
    own_only(ctx, unit)?;
    let axis = axis_arg(ctx, ctx.num(&args[at.axis])?, Err::ArgValue)?;
    let softness = percent(ctx, ctx.num(&args[at.softness])?, 0.0, 100.0, "SoftAct Softness")?;
    let ramp = match ctx.opt_num(args.get(at.ramp))? {
        Some(r) => percent(ctx, r, 100.0, f64::MAX, "SoftAct Ramp")?,
        None => 100.0,
    };
    servo(ctx).soft[axis - 1] = Some((softness, ramp));
    Ok(None)
}

/// `SoftDeact [\Ramp]`: every soft axis becomes stiff again.
pub(crate) fn soft_deact(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if let Some(r) = ctx.opt_num(args.first())? {
        percent(ctx, r, 100.0, f64::MAX, "SoftDeact Ramp")?;
    }
    servo(ctx).soft = [None; ROBOT_AXES];
    Ok(None)
}

/// `TuneServo MecUnit, Axis, TuneValue [\Type]`: one servo parameter of an axis in
/// percent of normal (\Type TUNE_DF when absent).
// uncertain: TuneValue is taken to range 1..500 % for every type (the manual's
// narrower ranges for some types are not checked); outside it, or an unknown Type,
// raises ERR_ARGVALERR.
pub(crate) fn tune_servo(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *TUNE_SERVO;
    let unit = unit_arg(ctx, args, 0)?;
    own_only(ctx, unit)?;
    let axis = axis_arg(ctx, ctx.num(&args[at.axis])?, Err::ArgValue)?;
    let value = percent(ctx, ctx.num(&args[at.tune_value])?, 1.0, 500.0, "TuneServo TuneValue")?;
    let ty = ctx.opt_num(args.get(at.ty))?.unwrap_or(0.0);
    if ty.fract() != 0.0 || !(0.0..TUNE_TYPES as f64).contains(&ty) {
        return Err(ctx.error(Err::ArgValue, format!("{ty} is not a tunetype")));
    }
    servo(ctx).tune[axis - 1][ty as usize] = value;
    Ok(None)
}

/// `TuneReset`: every axis's tuning back to 100 %.
pub(crate) fn tune_reset(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    servo(ctx).tune = [[100.0; TUNE_TYPES]; ROBOT_AXES];
    Ok(None)
}

/// `ActEventBuffer`: the configured event buffer is used again.
pub(crate) fn act_event_buffer(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    servo(ctx).event_buffer = true;
    mirror(ctx);
    Ok(None)
}

/// `DeactEventBuffer`: moves run without the event buffer.
pub(crate) fn deact_event_buffer(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    servo(ctx).event_buffer = false;
    mirror(ctx);
    Ok(None)
}

/// `SpeedLimAxis MechUnit, AxisNo, AxisSpeed`: the axis's speed limit (deg/s) for
/// while the system input LimitSpeed is set. An axis the unit does not have is
/// ERR_AXIS_PAR; a speed of 0 or less ERR_SPEEDLIM_VALUE.
// uncertain: the lowest speed the controller accepts is not public; any positive
// speed is taken.
pub(crate) fn speed_lim_axis(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SPEED_LIM_AXIS;
    let unit = unit_arg(ctx, args, 0)?;
    own_only(ctx, unit)?;
    let axis = axis_arg(ctx, ctx.num(&args[at.axis_no])?, Err::AxisPar)?;
    let speed = ctx.num(&args[at.axis_speed])?;
    if speed <= 0.0 || !speed.is_finite() {
        return Err(ctx.error(Err::SpeedLimValue, format!("SpeedLimAxis speed {speed} is too low")));
    }
    servo(ctx).axis_speed_limit[axis - 1] = Some(speed);
    Ok(None)
}

/// `SpeedLimCheckPoint RobSpeed`: the speed limit (mm/s) of the robot's check
/// points for while LimitSpeed is set; 0 or less is ERR_SPEEDLIM_VALUE.
// uncertain: as SpeedLimAxis, the lowest accepted speed is not public.
pub(crate) fn speed_lim_check_point(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let speed = ctx.num(&args[0])?;
    if speed <= 0.0 || !speed.is_finite() {
        return Err(ctx.error(Err::SpeedLimValue, format!("SpeedLimCheckPoint speed {speed} is too low")));
    }
    servo(ctx).check_point_limit = Some(speed);
    Ok(None)
}

/// `PFRestart([\Base] | [\Irpt])`: whether a path was cut by a power failure. A
/// `rapid run` controller never loses power: FALSE.
pub(crate) fn pf_restart(_ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Bool(false)))
}
