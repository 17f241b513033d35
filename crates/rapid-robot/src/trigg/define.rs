//! TriggIO, TriggEquip and TriggInt: an output set or an interrupt fired at a place
//! on the next trigger move's path. With `\Inhib` the persistent flag is read when the
//! robot gets there: TRUE sets the output to `\InhibSetValue` (0 without it) instead,
//! or fires no interrupt.

use super::super::robot::{Action, At, PathEvent};
use super::{check_value, define, inhib_place, place, refuse, Res, Special};
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value, ABSENT};

rapid_vm::ext::layout! {
    static TRIGG_IO: IoArgs = "TriggIO" {
        data: "TriggData", distance: "Distance", start: "Start", time: "Time", dop: "DOp", gop: "GOp", aop: "AOp",
        proc_id: "ProcID", set_value: "SetValue", set_dvalue: "SetDvalue", delay: "DODelay", inhib: "Inhib",
        inhib_value: "InhibSetValue", mode: "Mode",
    }
    static TRIGG_EQUIP: EquipArgs = "TriggEquip" {
        data: "TriggData", distance: "Distance", start: "Start", next: "Next", lag: "EquipLag", dop: "DOp", gop: "GOp",
        aop: "AOp", proc_id: "ProcID", set_value: "SetValue", set_dvalue: "SetDvalue", inhib: "Inhib",
        inhib_value: "InhibSetValue", mode: "Mode",
    }
    static TRIGG_INT: IntArgs = "TriggInt" {
        data: "TriggData", distance: "Distance", start: "Start", next: "Next", time: "Time", interrupt: "Interrupt",
        inhib: "Inhib", mode: "Mode",
    }
}

/// The output a trigger sets: the signal of `\DOp | \GOp | \AOp` (at `ops`) and the
/// value of `SetValue | SetDvalue` (at `value`, `dvalue`).
fn output(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    ops: [usize; 3],
    (value, dvalue): (usize, usize),
) -> Result<(u32, f64), RapidError> {
    let Some(signal) = ops.into_iter().find(|&i| present(args.get(i))) else {
        return Err(ctx.error(Err::ArgValue, "the trigger names no output (\\DOp, \\GOp or \\AOp)"));
    };
    let id = rapid_signals::signal(ctx, &args[signal])?;
    let set = if present(args.get(dvalue)) { ctx.num(&args[dvalue])? } else { ctx.num(&args[value])? };
    check_value(ctx, id, set)?;
    Ok((id, set))
}

/// The event of an output trigger: a plain set, or with `\Inhib` (at `inhib`, its
/// value `\InhibSetValue` at `inhib_value`) one decided at the place.
fn output_event(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    (signal, value): (u32, f64),
    (inhib, inhib_value_at): (usize, usize),
    at: At,
    shift: f64,
) -> Result<(PathEvent, Option<Special>), RapidError> {
    let Some(flag) = inhib_place(args, inhib) else {
        return Ok((PathEvent { at, shift, action: Action::Set { signal, value } }, None));
    };
    // uncertain: InhibSetValue is read when the trigger is defined, the flag when the
    // robot gets to the place.
    let inhib_value = ctx.opt_num(args.get(inhib_value_at))?.unwrap_or(0.0);
    check_value(ctx, signal, inhib_value)?;
    let special = Special::Inhibited { signal, value, inhib: flag, inhib_value };
    Ok((PathEvent { at, shift, action: Action::Special(0) }, Some(special)))
}

/// `TriggIO TriggData, Distance [\Start] | [\Time] [\DOp] | [\GOp] | [\AOp] SetValue |
/// SetDvalue [\DODelay] [\Inhib] [\InhibSetValue]`: set an output at a place on the
/// next TriggL/J/C path (`\DODelay` seconds later).
pub(crate) fn trigg_io(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let io = *TRIGG_IO;
    refuse(args, &[(io.proc_id, "\\ProcID"), (io.mode, "\\Mode")])?;
    let at = place(ctx, args, (io.distance, io.start, io.time))?;
    let set = output(ctx, args, [io.dop, io.gop, io.aop], (io.set_value, io.set_dvalue))?;
    let delay = ctx.opt_num(args.get(io.delay))?.unwrap_or(0.0);
    let (event, special) = output_event(ctx, args, set, (io.inhib, io.inhib_value), at, delay.max(0.0))?;
    define(ctx, &args[io.data], event, special)
}

/// `TriggEquip TriggData, Distance [\Start], EquipLag, …`: like TriggIO, the output set
/// EquipLag seconds earlier, so slow equipment acts at the place.
pub(crate) fn trigg_equip(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let eq = *TRIGG_EQUIP;
    refuse(args, &[(eq.next, "\\Next"), (eq.proc_id, "\\ProcID"), (eq.mode, "\\Mode")])?;
    let at = place(ctx, args, (eq.distance, eq.start, ABSENT))?;
    let lag = ctx.num(&args[eq.lag])?;
    let set = output(ctx, args, [eq.dop, eq.gop, eq.aop], (eq.set_value, eq.set_dvalue))?;
    let (event, special) = output_event(ctx, args, set, (eq.inhib, eq.inhib_value), at, -lag)?;
    define(ctx, &args[eq.data], event, special)
}

/// `TriggInt TriggData, Distance [\Start] | [\Time], Interrupt [\Inhib]`: an interrupt
/// at a place.
pub(crate) fn trigg_int(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let int = *TRIGG_INT;
    refuse(args, &[(int.next, "\\Next"), (int.mode, "\\Mode")])?;
    let at = place(ctx, args, (int.distance, int.start, int.time))?;
    let number = rapid_vm::ext::interrupt_number(ctx, &args[int.interrupt])?;
    let (action, special) = match inhib_place(args, int.inhib) {
        Some(inhib) => (Action::Special(0), Some(Special::InhibitedInterrupt { interrupt: number, inhib })),
        None => (Action::Interrupt(number), None),
    };
    define(ctx, &args[int.data], PathEvent { at, shift: 0.0, action }, special)
}
