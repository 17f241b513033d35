//! Clocks (§1.14) on the controller's virtual time: ClkReset, ClkStart, ClkStop,
//! ClkRead. A clock counts seconds while started; reading does not stop it.

use super::Ctx;
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Opaque, OpaqueState, Value};

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("ClkReset", clk_reset),
        super::native("ClkStart", clk_start),
        super::native("ClkStop", clk_stop),
        super::native("ClkRead", clk_read),
    ],
};

type Res = Result<Option<Value>, RapidError>;

/// A clock overflows after 2^32 ms (about 49.7 days).
const CLOCK_LIMIT_SECONDS: f64 = 4_294_967.295;

/// (accumulated seconds, start time when running) of the clock an argument names.
fn clock_state(ctx: &Ctx<'_>, arg: &Value) -> Result<(f64, Option<f64>, Opaque), RapidError> {
    match ctx.value(arg)? {
        Value::Opaque(opaque) => match opaque.state {
            OpaqueState::Clock { accumulated, started_at } => Ok((accumulated, started_at, *opaque)),
            // A fresh clock (OpaqueState::None); the checker lets only clocks reach here.
            _ => Ok((0.0, None, *opaque)),
        },
        _ => Err(ctx.error(Err::ArgValue, "a clock was expected")),
    }
}

fn set_clock(ctx: &mut Ctx<'_>, arg: &Value, mut opaque: Opaque, accumulated: f64, started_at: Option<f64>) -> Res {
    opaque.state = OpaqueState::Clock { accumulated, started_at };
    ctx.store(arg, Value::Opaque(Box::new(opaque)))?;
    Ok(None)
}

/// `ClkReset Clock`: stops the clock and sets it to zero.
pub(super) fn clk_reset(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (_, _, opaque) = clock_state(ctx, &args[0])?;
    set_clock(ctx, &args[0], opaque, 0.0, None)
}

/// `ClkStart Clock`: starts (or keeps running) the clock.
pub(super) fn clk_start(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (accumulated, started_at, opaque) = clock_state(ctx, &args[0])?;
    let now = ctx.time;
    set_clock(ctx, &args[0], opaque, accumulated, Some(started_at.unwrap_or(now)))
}

/// `ClkStop Clock`: stops the clock, keeping the time it counted.
pub(super) fn clk_stop(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (accumulated, started_at, opaque) = clock_state(ctx, &args[0])?;
    let total = accumulated + started_at.map_or(0.0, |start| ctx.time - start);
    set_clock(ctx, &args[0], opaque, total, None)
}

/// `ClkRead(Clock [\HighRes])`: seconds counted, to a millisecond (to a microsecond
/// with \HighRes); ERR_OVERFLOW past about 49.7 days.
pub(super) fn clk_read(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (accumulated, started_at, _) = clock_state(ctx, &args[0])?;
    let total = accumulated + started_at.map_or(0.0, |start| ctx.time - start);
    if total > CLOCK_LIMIT_SECONDS {
        return Err(ctx.error(Err::Overflow, "the clock ran past 4294967 seconds"));
    }
    let scale = if super::present(args.get(1)) { 1e6 } else { 1e3 };
    // The clock counts whole ticks; a difference of two controller times a rounding
    // error below a tick boundary (0.2999999999 s for a 0.3 s move) is that tick.
    let ticks = (total * scale + 1e-6).floor();
    Ok(Some(Value::Num((ticks / scale) as f32)))
}
