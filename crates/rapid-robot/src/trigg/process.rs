//! TriggRampAO and TriggSpeed: analog outputs driven along the path from a place on,
//! laid out at the 4 ms path resolution when the move is planned (see `path.rs`).

use super::super::robot::{Action, PathEvent};
use super::{analog_max, check_value, define, place, refuse, Res, Special};
use rapid_vm::ext::{present, Ctx, Err, Value, ABSENT};

rapid_vm::ext::layout! {
    static TRIGG_RAMP: RampArgs = "TriggRampAO" {
        data: "TriggData", distance: "Distance", start: "Start", next: "Next", lag: "EquipLag", signal: "AOutput",
        value: "SetValue", length: "RampLength", time: "Time", inhib: "Inhib", inhib_value: "InhibSetValue",
        mode: "Mode",
    }
    static TRIGG_SPEED: SpeedArgs = "TriggSpeed" {
        data: "TriggData", distance: "Distance", start: "Start", next: "Next", lag: "ScaleLag", signal: "AOp",
        scale: "ScaleValue", dip: "DipLag", err_do: "ErrDO", inhib: "Inhib", inhib_value: "InhibSetValue",
        mode: "Mode",
    }
}

/// `TriggRampAO TriggData, Distance [\Start], EquipLag, AOutput, SetValue, RampLength
/// [\Time]`: from the place on, the analog output goes in a straight ramp from its
/// value to SetValue over RampLength mm of path (seconds with `\Time`), EquipLag
/// seconds early.
// uncertain: the ramp starts from the output's value when the trigger move runs (with
// the outputs already ordered on the path before it), not re-read at the place.
pub(crate) fn trigg_ramp_ao(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let ramp = *TRIGG_RAMP;
    let options =
        [(ramp.next, "\\Next"), (ramp.inhib, "\\Inhib"), (ramp.inhib_value, "\\InhibSetValue"), (ramp.mode, "\\Mode")];
    refuse(args, &options)?;
    // RampLength's \Time is how the ramp is measured, not where the trigger is.
    let at = place(ctx, args, (ramp.distance, ramp.start, ABSENT))?;
    let lag = ctx.num(&args[ramp.lag])?;
    let signal = rapid_signals::signal(ctx, &args[ramp.signal])?;
    let to = ctx.num(&args[ramp.value])?;
    check_value(ctx, signal, to)?;
    let length = ctx.num(&args[ramp.length])?;
    if !length.is_finite() || length < 0.0 || !lag.is_finite() {
        return Err(ctx.error(Err::ArgValue, "TriggRampAO's RampLength must be 0 or more"));
    }
    let by_time = present(args.get(ramp.time));
    let special = Special::Ramp { signal, from: f64::NAN, to, length, by_time, lag };
    define(ctx, &args[ramp.data], PathEvent { at, shift: 0.0, action: Action::Special(0) }, Some(special))
}

/// `TriggSpeed TriggData, Distance [\Start], ScaleLag, AOp, ScaleValue [\DipLag]
/// [\ErrDO]`: from the place on, the analog output is ScaleValue × the TCP speed
/// (mm/s), ScaleLag seconds early (speed dips DipLag early), until the next
/// TriggSpeed or the robot stops at a point. A value above the output's limit stays
/// at the limit and sets ErrDO.
pub(crate) fn trigg_speed(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let sp = *TRIGG_SPEED;
    let options =
        [(sp.next, "\\Next"), (sp.inhib, "\\Inhib"), (sp.inhib_value, "\\InhibSetValue"), (sp.mode, "\\Mode")];
    refuse(args, &options)?;
    let at = place(ctx, args, (sp.distance, sp.start, ABSENT))?;
    let lag = ctx.num(&args[sp.lag])?;
    let signal = rapid_signals::signal(ctx, &args[sp.signal])?;
    let scale = ctx.num(&args[sp.scale])?;
    let dip = ctx.opt_num(args.get(sp.dip))?.unwrap_or(0.0);
    if !lag.is_finite() || !scale.is_finite() || !dip.is_finite() || dip < 0.0 {
        return Err(
            ctx.error(Err::ArgValue, "TriggSpeed's ScaleLag, ScaleValue and DipLag must be numbers (DipLag ≥ 0)")
        );
    }
    let err_do = if present(args.get(sp.err_do)) { Some(rapid_signals::signal(ctx, &args[sp.err_do])?) } else { None };
    let max = analog_max(ctx, signal);
    let special = Special::Speed { signal, scale, lag, dip, max, err_do };
    define(ctx, &args[sp.data], PathEvent { at, shift: 0.0, action: Action::Special(0) }, Some(special))
}
