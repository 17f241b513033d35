//! TriggRampAO and TriggSpeed: analog outputs driven along the path from a place on,
//! laid out at the 4 ms path resolution when the move is planned (see `path.rs`).

use super::super::super::{present, Ctx};
use super::super::robot::{Action, PathEvent};
use super::{analog_max, check_value, define, place, refuse, Res, Special};
use crate::errnames::Err;
use crate::value::Value;

/// `TriggRampAO TriggData, Distance [\Start], EquipLag, AOutput, SetValue, RampLength
/// [\Time]`: from the place on, the analog output goes in a straight ramp from its
/// value to SetValue over RampLength mm of path (seconds with `\Time`), EquipLag
/// seconds early.
// uncertain: the ramp starts from the output's value when the trigger move runs (with
// the outputs already ordered on the path before it), not re-read at the place.
pub(crate) fn trigg_ramp_ao(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(3, "\\Next"), (9, "\\Inhib"), (10, "\\InhibSetValue"), (11, "\\Mode")])?;
    let at = place(ctx, args, 2, None)?;
    let lag = ctx.num(&args[4])?;
    let signal = super::super::super::io::signal(ctx, &args[5])?;
    let to = ctx.num(&args[6])?;
    check_value(ctx, signal, to)?;
    let length = ctx.num(&args[7])?;
    if !length.is_finite() || length < 0.0 || !lag.is_finite() {
        return Err(ctx.error(Err::ArgValue, "TriggRampAO's RampLength must be 0 or more"));
    }
    let by_time = present(args.get(8));
    let special = Special::Ramp { signal, from: f64::NAN, to, length, by_time, lag };
    define(ctx, &args[0], PathEvent { at, shift: 0.0, action: Action::Special(0) }, Some(special))
}

/// `TriggSpeed TriggData, Distance [\Start], ScaleLag, AOp, ScaleValue [\DipLag]
/// [\ErrDO]`: from the place on, the analog output is ScaleValue × the TCP speed
/// (mm/s), ScaleLag seconds early (speed dips DipLag early), until the next
/// TriggSpeed or the robot stops at a point. A value above the output's limit stays
/// at the limit and sets ErrDO.
pub(crate) fn trigg_speed(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(3, "\\Next"), (9, "\\Inhib"), (10, "\\InhibSetValue"), (11, "\\Mode")])?;
    let at = place(ctx, args, 2, None)?;
    let lag = ctx.num(&args[4])?;
    let signal = super::super::super::io::signal(ctx, &args[5])?;
    let scale = ctx.num(&args[6])?;
    let dip = ctx.opt_num(args.get(7))?.unwrap_or(0.0);
    if !lag.is_finite() || !scale.is_finite() || !dip.is_finite() || dip < 0.0 {
        return Err(
            ctx.error(Err::ArgValue, "TriggSpeed's ScaleLag, ScaleValue and DipLag must be numbers (DipLag ≥ 0)")
        );
    }
    let err_do = if present(args.get(8)) { Some(super::super::super::io::signal(ctx, &args[8])?) } else { None };
    let max = analog_max(ctx, signal);
    let special = Special::Speed { signal, scale, lag, dip, max, err_do };
    define(ctx, &args[0], PathEvent { at, shift: 0.0, action: Action::Special(0) }, Some(special))
}
