//! `\Inpos` on move instructions (stoppointdata, manual §2.3 and the data type's
//! page): the move ends in a stop point of this kind, whatever its zone says.
//!
//! - `inpos` (1): the robot must be in position. The timing model has no servo
//!   convergence, so the stop lasts the `fine` settle time, but at least `mintime`
//!   and at most `maxtime` (the `position`/`speed` percentages are not modelled).
//! - `stoptime` (2): the robot stands `stoptime` seconds at the point.
//! - `fllwtime` (3): the robot follows the conveyor object it stops on for
//!   `followtime` seconds (a move in a conveyor's work object only).
//!
//! `progsynch` TRUE makes the program wait until the stop is over; FALSE lets it go
//! on as soon as the robot stands at the point.

use crate::RobotResources;
use rapid_vm::ext::{Ctx, Err, RapidError, Value};

/// The stop a move's `\Inpos` asks for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct StopPoint {
    /// How long the robot stands at the point before the move is done, s.
    pub(super) time: f64,
    /// Whether the program waits for the end of the stop.
    pub(super) progsynch: bool,
}

/// The stoppointdata kinds (`stoppoint`: inpos, stoptime, fllwtime).
const INPOS: i64 = 1;
const STOPTIME: i64 = 2;
const FLLWTIME: i64 = 3;

fn field(ctx: &Ctx<'_>, fields: &[Value], i: usize) -> Result<f64, RapidError> {
    let value = fields.get(i).and_then(Value::as_f64);
    value.filter(|v| v.is_finite()).ok_or_else(|| ctx.error(Err::ArgValue, "\\Inpos: a stoppointdata was expected"))
}

/// Reads `stoppointdata [type, progsynch, [position, speed, mintime, maxtime],
/// stoptime, followtime, signal, relation, checkvalue]`; `settle` is the time a
/// `fine` point stands.
// uncertain: how `progsynch` FALSE times the program (here: on when the robot
// stands at the point) and that the in-position time is the fine settle time.
pub(super) fn stop_point(ctx: &Ctx<'_>, value: &Value, settle: f64) -> Result<StopPoint, RapidError> {
    let Value::Record(record) = value else {
        return Err(ctx.error(Err::ArgValue, "\\Inpos: a stoppointdata was expected"));
    };
    let f = &record.fields;
    let kind = field(ctx, f, 0)?;
    let progsynch = matches!(f.get(1), Some(Value::Bool(true)));
    let negative = || ctx.error(Err::ArgValue, "\\Inpos: a stop point time is negative");
    let time = match kind.round() as i64 {
        INPOS => {
            let Some(Value::Record(inpos)) = f.get(2) else {
                return Err(ctx.error(Err::ArgValue, "\\Inpos: an inposdata was expected"));
            };
            let (min, max) = (field(ctx, &inpos.fields, 2)?, field(ctx, &inpos.fields, 3)?);
            if min < 0.0 || max < 0.0 {
                return Err(negative());
            }
            settle.max(min).min(max.max(min))
        }
        STOPTIME => {
            let time = field(ctx, f, 3)?;
            if time < 0.0 {
                return Err(negative());
            }
            time
        }
        FLLWTIME => {
            // uncertain: a follow time on a move in no conveyor's work object is taken to
            // stop execution (the manual ties it to conveyor tracking).
            let on_conveyor = ctx.resources.robot().following.open().is_some_and(|s| s.is_conveyor());
            if !on_conveyor {
                return Err(RapidError::fatal(
                    "\\Inpos with a follow time (fllwtime) needs a move in a conveyor's work object (WaitWObj)",
                ));
            }
            let time = field(ctx, f, 4)?;
            if time < 0.0 {
                return Err(negative());
            }
            time
        }
        _ => {
            return Err(
                ctx.error(Err::ArgValue, format!("\\Inpos: {kind} is no stop point type (inpos, stoptime, fllwtime)"))
            )
        }
    };
    Ok(StopPoint { time, progsynch })
}
