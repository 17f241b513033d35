//! TriggIO, TriggEquip and TriggInt: an output set or an interrupt fired at a place
//! on the next trigger move's path. With `\Inhib` the persistent flag is read when the
//! robot gets there: TRUE sets the output to `\InhibSetValue` (0 without it) instead,
//! or fires no interrupt.

use super::super::super::{present, Ctx};
use super::super::robot::{Action, At, PathEvent};
use super::{check_value, define, inhib_place, place, refuse, Res, Special};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// The output a trigger sets: the signal of `\DOp | \GOp | \AOp` at `first` and the
/// value of `SetValue | SetDvalue` at `value`.
fn output(ctx: &mut Ctx<'_>, args: &[Value], first: usize, value: usize) -> Result<(u32, f64), RapidError> {
    let Some(signal) = (first..first + 3).find(|&i| present(args.get(i))) else {
        return Err(ctx.error(Err::ArgValue, "the trigger names no output (\\DOp, \\GOp or \\AOp)"));
    };
    let id = super::super::super::io::signal(ctx, &args[signal])?;
    let set = if present(args.get(value + 1)) { ctx.num(&args[value + 1])? } else { ctx.num(&args[value])? };
    check_value(ctx, id, set)?;
    Ok((id, set))
}

/// The event of an output trigger: a plain set, or with `\Inhib` (at `inhib`, its
/// value `\InhibSetValue` at `inhib + 1`) one decided at the place.
fn output_event(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    (signal, value): (u32, f64),
    inhib: usize,
    at: At,
    shift: f64,
) -> Result<(PathEvent, Option<Special>), RapidError> {
    let Some(flag) = inhib_place(args, inhib) else {
        return Ok((PathEvent { at, shift, action: Action::Set { signal, value } }, None));
    };
    // uncertain: InhibSetValue is read when the trigger is defined, the flag when the
    // robot gets to the place.
    let inhib_value = ctx.opt_num(args.get(inhib + 1))?.unwrap_or(0.0);
    check_value(ctx, signal, inhib_value)?;
    let special = Special::Inhibited { signal, value, inhib: flag, inhib_value };
    Ok((PathEvent { at, shift, action: Action::Special(0) }, Some(special)))
}

/// `TriggIO TriggData, Distance [\Start] | [\Time] [\DOp] | [\GOp] | [\AOp] SetValue |
/// SetDvalue [\DODelay] [\Inhib] [\InhibSetValue]`: set an output at a place on the
/// next TriggL/J/C path (`\DODelay` seconds later).
pub(crate) fn trigg_io(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(7, "\\ProcID"), (13, "\\Mode")])?;
    let at = place(ctx, args, 2, Some(3))?;
    let set = output(ctx, args, 4, 8)?;
    let delay = ctx.opt_num(args.get(10))?.unwrap_or(0.0);
    let (event, special) = output_event(ctx, args, set, 11, at, delay.max(0.0))?;
    define(ctx, &args[0], event, special)
}

/// `TriggEquip TriggData, Distance [\Start], EquipLag, …`: like TriggIO, the output set
/// EquipLag seconds earlier, so slow equipment acts at the place.
pub(crate) fn trigg_equip(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(3, "\\Next"), (8, "\\ProcID"), (13, "\\Mode")])?;
    let at = place(ctx, args, 2, None)?;
    let lag = ctx.num(&args[4])?;
    let set = output(ctx, args, 5, 9)?;
    let (event, special) = output_event(ctx, args, set, 11, at, -lag)?;
    define(ctx, &args[0], event, special)
}

/// `TriggInt TriggData, Distance [\Start] | [\Time], Interrupt [\Inhib]`: an interrupt
/// at a place.
pub(crate) fn trigg_int(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse(args, &[(3, "\\Next"), (7, "\\Mode")])?;
    let at = place(ctx, args, 2, Some(4))?;
    let number = super::super::super::interrupts::interrupt_number(ctx, &args[5])?;
    let (action, special) = match inhib_place(args, 6) {
        Some(inhib) => (Action::Special(0), Some(Special::InhibitedInterrupt { interrupt: number, inhib })),
        None => (Action::Interrupt(number), None),
    };
    define(ctx, &args[0], PathEvent { at, shift: 0.0, action }, special)
}
