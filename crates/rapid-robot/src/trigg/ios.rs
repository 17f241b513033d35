//! TriggLIOs and TriggJIOs: moves that set the outputs listed in triggios,
//! triggstrgo and triggiosdnum arrays (`used`, `distance`, `start`, `equiplag`,
//! `signalname`, `setvalue`, `xxx`), each signal found by its name when the move runs.

use super::super::moves::{joint_move, linear_move, Layout};
use super::super::robot::{Action, At, PathEvent};
use super::moves::{TRIGG_J_IOS, TRIGG_L_IOS};
use super::{check_value, Res};
use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value};

/// The output events of one element of a trigger array (None when `used` is FALSE).
fn element(ctx: &mut Ctx<'_>, elem: &Value) -> Result<Option<PathEvent>, RapidError> {
    let Value::Record(record) = elem else { return Ok(None) };
    let field = |i: usize| record.fields.get(i).cloned().unwrap_or(Value::Absent);
    if field(0) != Value::Bool(true) {
        return Ok(None);
    }
    let number = |v: Value| v.as_f64().unwrap_or(f64::NAN);
    let distance = number(field(1));
    let start = field(2) == Value::Bool(true);
    let lag = number(field(3));
    if !distance.is_finite() || distance < 0.0 || !lag.is_finite() {
        return Err(ctx.error(Err::ArgValue, "a trigger's distance must be 0 or more"));
    }
    let Value::Str(name) = field(4) else { return Ok(None) };
    let value = match field(5) {
        // triggstrgo: the value as a string of digits (stringdig).
        Value::Str(digits) => match digits.parse::<u64>() {
            Ok(v) => v as f64,
            Err(_) => return Err(ctx.error(Err::ArgValue, format!("setvalue \"{digits}\" is not a string of digits"))),
        },
        other => number(other),
    };
    let id = ctx.resources.io().system.as_ref().and_then(|io| io.id(&name));
    let Some(id) = id else {
        return Err(ctx.error(Err::SigName, format!("there is no I/O signal named {name}")));
    };
    let fault = ctx.resources.io().system.as_ref().and_then(|io| io.read(id).err());
    if let Some(fault) = fault {
        return Err(rapid_signals::io_error(ctx, &fault));
    }
    let output = ctx.resources.io().system.as_ref().and_then(|io| io.def(id)).is_some_and(|d| !d.kind.is_input());
    if !output {
        return Err(ctx.error(Err::ArgValue, format!("signal {name} is no output")));
    }
    check_value(ctx, id, value)?;
    let at = if start { At::AfterStart(distance) } else { At::BeforePoint(distance) };
    Ok(Some(PathEvent { at, shift: -lag, action: Action::Set { signal: id, value } }))
}

/// The events of `\TriggData1`, `\TriggData2` and `\TriggData3` (the arguments up to Zone).
fn io_events(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout) -> Result<Vec<PathEvent>, RapidError> {
    let mut events = Vec::new();
    for idx in layout.trigg..layout.zone {
        if !present(args.get(idx)) {
            continue;
        }
        let Value::Array(array) = ctx.value(&args[idx])? else { continue };
        for elem in &array.elems {
            events.extend(element(ctx, elem)?);
        }
    }
    Ok(events)
}

/// `TriggLIOs`: MoveL setting the outputs of its trigger arrays.
pub(crate) fn trigg_l_ios(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = io_events(ctx, args, &TRIGG_L_IOS)?;
    linear_move(ctx, args, &TRIGG_L_IOS, events)
}

/// `TriggJIOs`: MoveJ setting the outputs of its trigger arrays.
pub(crate) fn trigg_j_ios(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = io_events(ctx, args, &TRIGG_J_IOS)?;
    joint_move(ctx, args, &TRIGG_J_IOS, events)
}
