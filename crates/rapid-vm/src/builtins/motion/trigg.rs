//! Triggers on the path (§1.8): TriggIO, TriggEquip and TriggInt define what happens
//! where (an output set, an interrupt fired, at a distance before the move's point,
//! after its start, or a time before it); TriggL, TriggJ and TriggC are moves that
//! fire up to eight of them. A triggdata holds the index of its definition in the
//! robot's table.

use super::super::{present, Ctx};
use super::moves::{circular_move, joint_move, linear_move, Layout, NONE};
use super::robot::{Action, At, PathEvent};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Opaque, OpaqueState, Value};

type Res = Result<Option<Value>, RapidError>;

/// Options of the trigger definitions not modelled: execution stops, naming them.
fn refuse(args: &[Value], options: &[(usize, &str)]) -> Result<(), RapidError> {
    for &(idx, name) in options {
        if present(args.get(idx)) {
            return Err(RapidError::fatal(format!("{name} on a trigger is not supported by `rapid run` yet")));
        }
    }
    Ok(())
}

/// Where the trigger is: Distance mm before the point, after the start (`\Start`), or
/// seconds before the point (`\Time`).
fn place(ctx: &Ctx<'_>, args: &[Value], start: usize, time: Option<usize>) -> Result<At, RapidError> {
    let distance = ctx.num(&args[1])?;
    if !distance.is_finite() || distance < 0.0 {
        return Err(ctx.error(Err::ArgValue, "a trigger's Distance must be 0 or more"));
    }
    Ok(if present(args.get(start)) {
        At::AfterStart(distance)
    } else if time.is_some_and(|t| present(args.get(t))) {
        At::SecondsBefore(distance)
    } else {
        At::BeforePoint(distance)
    })
}

/// The output a trigger sets: the signal of `\DOp | \GOp | \AOp` at `first` and the
/// value of `SetValue | SetDvalue` at `value`.
fn output(ctx: &mut Ctx<'_>, args: &[Value], first: usize, value: usize) -> Result<Action, RapidError> {
    let Some(signal) = (first..first + 3).find(|&i| present(args.get(i))) else {
        return Err(ctx.error(Err::ArgValue, "the trigger names no output (\\DOp, \\GOp or \\AOp)"));
    };
    let id = super::super::io::signal(ctx, &args[signal])?;
    let set = if present(args.get(value + 1)) { ctx.num(&args[value + 1])? } else { ctx.num(&args[value])? };
    Ok(Action::Set { signal: id, value: set })
}

/// Stores a trigger definition in its triggdata.
fn define(ctx: &mut Ctx<'_>, arg: &Value, event: PathEvent) -> Res {
    let (opaque, handle) = ctx.handle_arg(arg, "a triggdata")?;
    let triggers = &mut ctx.resources.robot.triggers;
    let index = match handle.map(|h| h as usize).filter(|&h| h < triggers.len()) {
        Some(h) => {
            triggers[h] = event;
            h
        }
        None => {
            triggers.push(event);
            triggers.len() - 1
        }
    };
    let data = Opaque { ty: opaque.ty, state: OpaqueState::Handle(index as u32) };
    ctx.store(arg, Value::Opaque(Box::new(data)))?;
    Ok(None)
}

/// `TriggIO TriggData, Distance [\Start] | [\Time] [\DOp] | [\GOp] | [\AOp] SetValue |
/// SetDvalue [\DODelay]`: set an output at a place on the next TriggL/J/C path
/// (`\DODelay` seconds later).
pub(crate) fn trigg_io(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(7, "\\ProcID"), (11, "\\Inhib"), (12, "\\InhibSetValue"), (13, "\\Mode")])?;
    let at = place(ctx, args, 2, Some(3))?;
    let action = output(ctx, args, 4, 8)?;
    let delay = ctx.opt_num(args.get(10))?.unwrap_or(0.0);
    define(ctx, &args[0], PathEvent { at, shift: delay.max(0.0), action })
}

/// `TriggEquip TriggData, Distance [\Start], EquipLag, …`: like TriggIO, the output set
/// EquipLag seconds earlier, so slow equipment acts at the place.
pub(crate) fn trigg_equip(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(3, "\\Next"), (8, "\\ProcID"), (11, "\\Inhib"), (12, "\\InhibSetValue"), (13, "\\Mode")])?;
    let at = place(ctx, args, 2, None)?;
    let lag = ctx.num(&args[4])?;
    let action = output(ctx, args, 5, 9)?;
    define(ctx, &args[0], PathEvent { at, shift: -lag, action })
}

/// `TriggInt TriggData, Distance [\Start] | [\Time], Interrupt`: an interrupt at a place.
pub(crate) fn trigg_int(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(3, "\\Next"), (6, "\\Inhib"), (7, "\\Mode")])?;
    let at = place(ctx, args, 2, Some(4))?;
    let number = ctx.num(&args[5])?;
    if number < 1.0 || number.fract() != 0.0 || ctx.resources.interrupts.get_mut(number as u32).is_none() {
        return Err(ctx.error(Err::UnknownInterrupt, "the intnum is not connected to a trap (CONNECT)"));
    }
    define(ctx, &args[0], PathEvent { at, shift: 0.0, action: Action::Interrupt(number as u32) })
}

/// The triggers a TriggL/J/C names: Trigg_1 (or every element of TriggArray) and T2…T8.
fn triggers_of(ctx: &Ctx<'_>, args: &[Value], first: usize) -> Result<Vec<PathEvent>, RapidError> {
    let mut handles = Vec::new();
    let mut add = |value: Value| match value {
        Value::Opaque(o) => {
            if let OpaqueState::Handle(h) = o.state {
                handles.push(h as usize);
            }
        }
        Value::Array(array) => {
            for elem in array.elems {
                if let Value::Opaque(o) = elem {
                    if let OpaqueState::Handle(h) = o.state {
                        handles.push(h as usize);
                    }
                }
            }
        }
        _ => {}
    };
    for idx in (first..first + 2).chain(first + 2..first + 9) {
        if present(args.get(idx)) {
            add(ctx.value(&args[idx])?);
        }
    }
    let triggers = &ctx.resources.robot.triggers;
    handles
        .into_iter()
        .map(|h| {
            triggers.get(h).copied().ok_or_else(|| ctx.error(Err::ArgValue, "a triggdata was never defined (TriggIO)"))
        })
        .collect()
}

const TRIGG_L: Layout = Layout {
    conc: 0,
    cir: None,
    to: 1,
    id: 2,
    speed: 3,
    v: NONE,
    t: 4,
    zone: 14,
    z: NONE,
    inpos: 15,
    tool: 16,
    wobj: 17,
    corr: Some(18),
};
const TRIGG_J: Layout = Layout { corr: None, ..TRIGG_L };
const TRIGG_C: Layout = Layout {
    cir: Some(1),
    to: 2,
    id: 3,
    speed: 4,
    t: 5,
    zone: 15,
    inpos: 16,
    tool: 17,
    wobj: 18,
    corr: Some(19),
    ..TRIGG_L
};

/// `TriggL`: MoveL firing its triggers.
pub(crate) fn trigg_l(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = triggers_of(ctx, args, 5)?;
    linear_move(ctx, args, &TRIGG_L, events)
}

/// `TriggJ`: MoveJ firing its triggers.
pub(crate) fn trigg_j(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = triggers_of(ctx, args, 5)?;
    joint_move(ctx, args, &TRIGG_J, events)
}

/// `TriggC`: MoveC firing its triggers.
pub(crate) fn trigg_c(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let events = triggers_of(ctx, args, 6)?;
    circular_move(ctx, args, &TRIGG_C, events)
}
