//! Motion settings instructions (manual §1.7): VelSet, AccSet, ConfJ, ConfL,
//! SingArea, CirPathMode, GripLoad, PathResol, CornerPathWarning, SpeedRefresh,
//! CSpeedOverride, and the program displacement and external axis offset settings
//! PDispSet, PDispOff, EOffsSet, EOffsOff. Each changes [`super::Settings`] and
//! mirrors the readable part into C_MOTSET / C_PROGDISP.

use crate::RobotResources;
use nalgebra::{Isometry3, Translation3};

use super::{frame, mirror, CirPathMode, Load, Settings, SingMode};
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// Applies `change` to the settings and mirrors them into the system data.
fn update(ctx: &mut Ctx<'_>, change: impl FnOnce(&mut Settings)) -> Res {
    change(&mut ctx.resources.motion_mut().settings);
    mirror(ctx);
    Ok(None)
}

/// `VelSet Override, Max`: programmed speeds scaled by Override percent, TCP speed
/// capped at Max mm/s.
// uncertain: the manual states no range; a zero or negative Override or Max (a
// robot that could never move) raises ERR_ARGVALERR here. Overrides above 100 are
// allowed (the speeds are still capped by Max).
pub(crate) fn vel_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (oride, max) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    if oride <= 0.0 || max <= 0.0 {
        return Err(ctx.error(Err::ArgValue, "VelSet needs a positive Override and Max"));
    }
    update(ctx, |s| {
        s.vel_override = oride;
        s.vel_max = max;
    })
}

/// One AccSet percentage: at most 100, raised to `floor` when lower (manual: "an
/// input value < 20 % gives 20 %" for Acc, 10 % for the ramps).
// uncertain: the manual gives 100 % as the maximum without saying what a larger
// value does; it raises ERR_ARGVALERR here.
fn acc_percent(ctx: &Ctx<'_>, value: f64, floor: f64, what: &str) -> Result<f64, RapidError> {
    if value > 100.0 {
        return Err(ctx.error(Err::ArgValue, format!("AccSet {what} is above 100 %")));
    }
    Ok(value.max(floor))
}

/// `AccSet Acc, Ramp [\FinePointRamp]`: acceleration and its rate of change in
/// percent of normal; FinePointRamp defaults to Ramp.
pub(crate) fn acc_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let acc = acc_percent(ctx, ctx.num(&args[0])?, 20.0, "Acc")?;
    let ramp = acc_percent(ctx, ctx.num(&args[1])?, 10.0, "Ramp")?;
    let fine = match ctx.opt_num(args.get(2))? {
        Some(value) => acc_percent(ctx, value, 10.0, "FinePointRamp")?,
        None => ramp,
    };
    update(ctx, |s| {
        s.acc = acc;
        s.ramp = ramp;
        s.fine_point_ramp = fine;
    })
}

/// `\On` unless `\Off` is passed.
// uncertain: with neither switch the instruction is taken as \On.
fn on_unless_off(args: &[Value]) -> bool {
    !present(args.get(1))
}

/// `ConfJ [\On] | [\Off]`: configuration control of joint moves.
pub(crate) fn conf_j(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let on = on_unless_off(args);
    update(ctx, |s| s.conf_j = on)
}

/// `ConfL [\On] | [\Off]`: configuration monitoring of linear and circular moves.
pub(crate) fn conf_l(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let on = on_unless_off(args);
    update(ctx, |s| s.conf_l = on)
}

/// `SingArea [\Wrist] | [\LockAxis4] | [\Off]`.
// uncertain: with no switch the instruction is taken as \Off.
pub(crate) fn sing_area(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let mode = if present(args.first()) {
        SingMode::Wrist
    } else if present(args.get(1)) {
        SingMode::LockAxis4
    } else {
        SingMode::Off
    };
    update(ctx, |s| s.sing = mode)
}

/// `CirPathMode [\PathFrame] | [\ObjectFrame] | [\CirPointOri] | [\Wrist45] |
/// [\Wrist46] | [\Wrist56]`; no switch means \PathFrame.
pub(crate) fn cir_path_mode(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    const MODES: [CirPathMode; 6] = [
        CirPathMode::PathFrame,
        CirPathMode::ObjectFrame,
        CirPathMode::CirPointOri,
        CirPathMode::Wrist45,
        CirPathMode::Wrist46,
        CirPathMode::Wrist56,
    ];
    let mode = (0..MODES.len()).find(|&i| present(args.get(i))).map_or(CirPathMode::PathFrame, |i| MODES[i]);
    update(ctx, |s| s.cir_path_mode = mode)
}

/// A loaddata value.
fn load(ctx: &Ctx<'_>, value: &Value) -> Result<Load, RapidError> {
    let bad = || ctx.error(Err::ArgValue, "a loaddata was expected");
    let Value::Record(record) = value else { return Err(bad()) };
    let [mass, cog, aom, ix, iy, iz] = &record.fields[..] else { return Err(bad()) };
    let cog = frame::vector(ctx, cog)?;
    let aom = frame::quaternion(ctx, aom)?;
    let number = |v: &Value| v.as_f64().ok_or_else(bad);
    Ok(Load {
        mass: number(mass)?,
        cog: [cog.x, cog.y, cog.z],
        aom: [aom.w, aom.i, aom.j, aom.k],
        inertia: [number(ix)?, number(iy)?, number(iz)?],
    })
}

/// `GripLoad Load`: the payload now in the gripper (load0 when released).
// uncertain: the controller checks load data when the robot moves; a negative mass
// or negative moment of inertia raises ERR_ARGVALERR here at once.
// The load becomes the active payload (GetSysData).
pub(crate) fn grip_load(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    set_payload(ctx, &ctx.value(&args[0])?)?;
    super::sysdata::activate_arg(ctx, &args[0], 0, super::sysdata::LOAD);
    Ok(None)
}

/// Makes a loaddata value the payload in the gripper (GripLoad, SetSysData).
pub(crate) fn set_payload(ctx: &mut Ctx<'_>, value: &Value) -> Result<(), RapidError> {
    let load = load(ctx, value)?;
    if load.mass < 0.0 || load.inertia.iter().any(|&i| i < 0.0) {
        return Err(ctx.error(Err::ArgValue, "the payload needs a mass and inertia of at least 0"));
    }
    update(ctx, |s| s.grip_load = load)?;
    Ok(())
}

/// `PathResol PathSampleTime`: path resolution in percent of the configured one,
/// 25..400 (manual).
// uncertain: a value outside 25..400 raises ERR_ARGVALERR.
pub(crate) fn path_resol(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let percent = ctx.num(&args[0])?;
    if !(25.0..=400.0).contains(&percent) {
        return Err(ctx.error(Err::ArgValue, "PathResol takes 25 to 400 percent"));
    }
    update(ctx, |s| s.path_resol = percent)
}

/// `MotionProcessModeSet Mode`: the motion process mode. OPTIMAL_CYCLE_TIME_MODE is the
/// controller's default, the mode every move is planned in: it changes nothing. The
/// other modes trade cycle time for accuracy through accelerations and servo tuning
/// whose values ABB does not publish, so they stop execution ("not supported yet")
/// rather than run with the default's timing.
pub(crate) fn motion_process_mode_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    const OPTIMAL_CYCLE_TIME_MODE: f64 = 1.0;
    let mode = ctx.num(&args[0])?;
    if mode == OPTIMAL_CYCLE_TIME_MODE {
        return Ok(None);
    }
    // The catalogue's motionprocessmode constants, by value.
    const NAMES: [&str; 8] = [
        "OPTIMAL_CYCLE_TIME_MODE",
        "LOW_SPEED_ACCURACY_MODE",
        "LOW_SPEED_STIFF_MODE",
        "ACCURACY_MODE",
        "MPM_USER_MODE_1",
        "MPM_USER_MODE_2",
        "MPM_USER_MODE_3",
        "MPM_USER_MODE_4",
    ];
    let known = (mode.fract() == 0.0 && (1.0..=8.0).contains(&mode)).then(|| NAMES[mode as usize - 1]);
    let Some(name) = known else {
        return Err(ctx.error(Err::ArgValue, format!("{mode} is no motion process mode")));
    };
    Err(RapidError::fatal(format!(
        "MotionProcessModeSet {name}: motion process modes other than OPTIMAL_CYCLE_TIME_MODE are not \
         supported yet (their accelerations and servo tuning are not public)"
    )))
}

/// `CornerPathWarning Active`: whether corner path failures are reported.
pub(crate) fn corner_path_warning(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let active = match ctx.value(&args[0])? {
        Value::Bool(b) => b,
        _ => return Err(ctx.error(Err::ArgValue, "a bool was expected")),
    };
    update(ctx, |s| s.corner_path_warning = active)
}

/// `SpeedRefresh Override`: the task's speed override, 0..100 percent; outside it
/// ERR_SPEED_REFRESH_LIM (manual).
pub(crate) fn speed_refresh(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let percent = ctx.num(&args[0])?;
    if !(0.0..=100.0).contains(&percent) {
        return Err(ctx.error(Err::SpeedRefreshLim, "SpeedRefresh takes 0 to 100 percent"));
    }
    update(ctx, |s| s.speed_refresh = percent)
}

/// `CSpeedOverride([\CTask])`: the operator's speed override (the controller state,
/// `rapid run --speed-override`, 100 unless told); with \CTask the override of this
/// task, which SpeedRefresh sets.
// uncertain: the task's value is the operator's override scaled by SpeedRefresh.
pub(crate) fn c_speed_override(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let operator = ctx.resources.controller.speed_override;
    let percent = if present(args.first()) {
        operator * ctx.resources.motion_mut().settings.speed_refresh / 100.0
    } else {
        operator
    };
    Ok(Some(Value::Num(percent as f32)))
}

/// `PDispSet DispFrame`: program displacement with the given frame.
// uncertain: the orientation is stored normalised (C_PROGDISP shows it so).
pub(crate) fn pdisp_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let disp = frame::frame(ctx, &ctx.value(&args[0])?)?;
    update(ctx, |s| s.pdisp = disp)
}

/// Makes `disp` the program displacement (PDispOn).
pub(super) fn set_pdisp(ctx: &mut Ctx<'_>, disp: Isometry3<f64>) -> Res {
    update(ctx, |s| s.pdisp = disp)
}

/// Sets the external axis offsets (EOffsOn).
pub(super) fn set_eoffs(ctx: &mut Ctx<'_>, offsets: [f64; 6]) -> Res {
    update(ctx, |s| s.eoffs = offsets)
}

/// `PDispOff`: no program displacement.
pub(crate) fn pdisp_off(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    update(ctx, |s| s.pdisp = Isometry3::from_parts(Translation3::identity(), nalgebra::UnitQuaternion::identity()))
}

/// `EOffsSet EAxOffs`: offsets for the external axes (mm or degrees).
pub(crate) fn eoffs_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let offsets = frame::extjoint(ctx, &ctx.value(&args[0])?)?;
    update(ctx, |s| s.eoffs = offsets)
}

/// `EOffsOff`: no external axis offsets.
pub(crate) fn eoffs_off(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    update(ctx, |s| s.eoffs = [0.0; 6])
}

/// The least acceleration limit PathAccLim and WorldAccLim take, m/s².
// uncertain: the manual's minimum as we remember it; a smaller positive value is
// raised to it, zero or less is ERR_ARGVALERR.
const MIN_ACC_LIMIT: f64 = 0.1;

/// An acceleration limit argument (m/s²), or ERR_ARGVALERR.
fn acc_limit(ctx: &Ctx<'_>, value: f64, what: &str) -> Result<f64, RapidError> {
    if !value.is_finite() || value <= 0.0 {
        return Err(ctx.error(Err::ArgValue, format!("{what} must be a positive acceleration in m/s²")));
    }
    Ok(value.max(MIN_ACC_LIMIT))
}

/// `PathAccLim AccLim [\AccMax] DecelLim [\DecelMax]`: limits (or frees) the TCP's
/// acceleration and deceleration along the path, in m/s². A limit switched on needs
/// its value.
// uncertain: AccLim TRUE without \AccMax (and DecelLim without \DecelMax) raises
// ERR_ARGVALERR; the limits bound linear and circular moves (the path of a joint
// move is not the TCP's).
pub(crate) fn path_acc_lim(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let limit = |ctx: &Ctx<'_>, on: usize, value: usize, what: &str| -> Result<Option<f64>, RapidError> {
        if !matches!(ctx.value(&args[on])?, Value::Bool(true)) {
            return Ok(None);
        }
        match ctx.opt_num(args.get(value))? {
            Some(v) => Ok(Some(acc_limit(ctx, v, what)?)),
            None => Err(ctx.error(Err::ArgValue, format!("a limit switched on needs \\{what}"))),
        }
    };
    let acc = limit(ctx, 0, 1, "AccMax")?;
    let decel = limit(ctx, 2, 3, "DecelMax")?;
    update(ctx, |s| {
        s.acc_max = acc;
        s.decel_max = decel;
    })
}

/// `WorldAccLim [\On] | [\Off]`: limits the tool's acceleration in the world frame to
/// On m/s² (it bounds both the path's acceleration and its braking), or frees it.
// uncertain: neither switch given frees it, as \Off does.
pub(crate) fn world_acc_lim(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let limit = match ctx.opt_num(args.first())? {
        Some(v) => Some(acc_limit(ctx, v, "On")?),
        None => None,
    };
    update(ctx, |s| s.world_acc_max = limit)
}
