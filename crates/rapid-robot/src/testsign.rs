//! Test signals (§1.18): TestSignDefine, TestSignReset, TestSignRead. A channel
//! watches one signal of one axis of the task's robot; TestSignRead gives its value
//! at the time of reading, taken from the simulated robot.
//!
//! The signals: the motor angle (resolver_angle, rad), the motor speed and its
//! reference (speed, speed_ref, rad/s; equal, as the simulated robot follows its
//! reference exactly), the torque reference (torque_ref, Nm; the static holding
//! torque of `torque.rs`), and the two digital inputs (0: none are wired).
// uncertain: ABB's gear ratios are not public; with a ratio of 1 the motor angle and
// speed are the axis's, in radians. The real resolver angle wraps within one motor
// turn; ours does not.

use super::units::{axis_arg, own_only, unit_arg};
use crate::RobotResources;
use rapid_vm::ext::{Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// Channels 1..=12.
pub const CHANNELS: usize = 12;

/// The shortest sample time, s: the controller's 4 ms; shorter ones are raised to it.
const MIN_SAMPLE_TIME: f64 = 0.004;

/// Over how long a speed is measured (backwards from the time of reading), s.
const SPEED_WINDOW: f64 = 0.001;

// The values of the testsignal constants (catalogue data.rs).
const RESOLVER_ANGLE: f64 = 1.0;
const SPEED_REF: f64 = 4.0;
const SPEED: f64 = 6.0;
const TORQUE_REF: f64 = 9.0;
const DIG_INPUT1: f64 = 102.0;
const DIG_INPUT2: f64 = 103.0;

/// What a channel watches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TestSignal {
    pub signal: f64,
    /// The axis, 1..=6.
    pub axis: usize,
    pub sample_time: f64,
}

/// The channel number of an argument, 1..=12.
// uncertain: another channel raises ERR_ARGVALERR.
fn channel(ctx: &Ctx<'_>, value: f64) -> Result<usize, RapidError> {
    if value.fract() == 0.0 && (1.0..=CHANNELS as f64).contains(&value) {
        return Ok(value as usize);
    }
    Err(ctx.error(Err::ArgValue, format!("test signal channel {value} is not 1..12")))
}

rapid_vm::ext::layout! {
    static TEST_SIGN_DEFINE: TestSignDefineArgs = "TestSignDefine" {
        mech_unit: "MechUnit", axis: "Axis", sample_time: "SampleTime",
    }
}

/// `TestSignDefine Channel, SignalId, MechUnit, Axis, SampleTime`: the channel
/// watches a signal of an axis; a sample time below 4 ms is taken as 4 ms.
// uncertain: an unknown SignalId or a negative SampleTime raises ERR_ARGVALERR.
pub(crate) fn test_sign_define(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *TEST_SIGN_DEFINE;
    let channel = channel(ctx, ctx.num(&args[0])?)?;
    let signal = ctx.num(&args[1])?;
    if ![RESOLVER_ANGLE, SPEED_REF, SPEED, TORQUE_REF, DIG_INPUT1, DIG_INPUT2].contains(&signal) {
        return Err(ctx.error(Err::ArgValue, format!("{signal} is not a test signal")));
    }
    let unit = unit_arg(ctx, args, at.mech_unit)?;
    own_only(ctx, unit)?;
    let axis = axis_arg(ctx, ctx.num(&args[at.axis])?, Err::ArgValue)?;
    let sample_time = ctx.num(&args[at.sample_time])?;
    if sample_time.is_nan() || sample_time < 0.0 || sample_time.is_infinite() {
        return Err(ctx.error(Err::ArgValue, format!("sample time {sample_time} is not a time")));
    }
    let sample_time = sample_time.max(MIN_SAMPLE_TIME);
    ctx.resources.motion_mut().servo.test_signals[channel - 1] = Some(TestSignal { signal, axis, sample_time });
    Ok(None)
}

/// `TestSignReset`: every channel is free again.
pub(crate) fn test_sign_reset(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    ctx.resources.motion_mut().servo.test_signals = Default::default();
    Ok(None)
}

/// `TestSignRead(Channel)`: the channel's signal now; 0 on a channel not defined.
// uncertain: reading a channel that has no signal gives 0 (not an error).
pub(crate) fn test_sign_read(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let channel = channel(ctx, ctx.num(&args[0])?)?;
    let Some(def) = ctx.resources.motion_mut().servo.test_signals[channel - 1] else {
        return Ok(Some(Value::Num(0.0)));
    };
    let i = def.axis - 1;
    let now = ctx.time;
    let value = if def.signal == RESOLVER_ANGLE {
        ctx.resources.robot_mut().joints_at(now)[i].to_radians()
    } else if def.signal == SPEED || def.signal == SPEED_REF {
        // Read the earlier time first: reading moves the robot's queue forward.
        let before = ctx.resources.robot_mut().joints_at((now - SPEED_WINDOW).max(0.0))[i];
        let here = ctx.resources.robot_mut().joints_at(now)[i];
        let dt = now - (now - SPEED_WINDOW).max(0.0);
        if dt > 0.0 {
            (here - before).to_radians() / dt
        } else {
            0.0
        }
    } else if def.signal == TORQUE_REF {
        super::torque::axis_torques(ctx)[i]
    } else {
        0.0
    };
    Ok(Some(Value::Num(value as f32)))
}
