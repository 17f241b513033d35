//! Program flow and system built-ins: WaitTime, Stop, Break, BookErrNo, Dim.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("RemainingRetries", remaining_retries),
        super::native("ResetRetryCount", reset_retry_count),
        super::native("SkipWarn", skip_warn),
        super::native("WaitTime", wait_time),
        super::native("Stop", stop),
        super::native("ExitCycle", exit_cycle),
        super::native("Break", break_).compiled_as(super::Compiled::Break),
        super::native("BookErrNo", book_err_no),
        super::native("Dim", dim),
        super::native("IsPers", is_pers),
        super::native("IsVar", is_var),
        super::native("ExecHandler", exec_handler),
        super::native("ExecLevel", exec_level),
    ],
};

/// `WaitTime [\InPos] Time`: waits `Time` seconds of controller time; with `\InPos` from
/// when the robot stands at the end of its last move (a fly-by point there becomes a stop
/// point: §2.3, the instruction that ends a \Conc sequence).
pub(super) fn wait_time(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    if args.len() > 1 && present(args.first()) && !super::stands_still(ctx)? {
        return Ok(None);
    }
    let time_arg = args.iter().rev().find(|a| present(Some(a))).ok_or_else(|| ctx.error(Err::ArgValue, "no time"))?;
    let seconds = ctx.num(time_arg)?;
    if seconds < 0.0 {
        return Err(ctx.error(Err::ArgValue, "WaitTime needs a time of 0 or more seconds"));
    }
    // While interrupts can fire, the wait ends at the next one due, so its trap runs in
    // time (§1.11: traps run during waits), and then goes on for the rest. An interrupt
    // another task causes (a persistent, a message) has no time: the wait re-checks, so
    // the controller resumes it when that task changes something.
    let due = super::interrupts::next_due(ctx);
    let here = (ctx.chain.len(), ctx.chain.last().map_or(0, |f| f.position().1));
    let resumed = match ctx.resources.waiting {
        Some((depth, pc, at)) if (depth, pc) == here => Some(at),
        _ => None,
    };
    if due.is_none() && !ctx.resources.interrupts.active() {
        // A wait a trap cut short goes on for the rest of its time, not afresh.
        ctx.resources.waiting = None;
        let rest = resumed.map_or(seconds, |at| at + seconds - ctx.time);
        if rest > 0.0 {
            ctx.wait = Some(rest);
        }
        return Ok(None);
    }
    let started = resumed.unwrap_or(ctx.time);
    let end = started + seconds;
    if ctx.time >= end {
        ctx.resources.waiting = None;
        return Ok(None);
    }
    ctx.resources.waiting = Some((here.0, here.1, started));
    ctx.wait = Some((due.map_or(end, |due| end.min(due)) - ctx.time).max(1e-6));
    ctx.stop = super::StopKind::Repeat;
    Ok(None)
}

/// `Stop [\NoRegain] | [\AllMoveTasks]`: halts the program. In UNDO context it is
/// ignored, with its switches, and an event-log warning is written (§1.13).
pub(super) fn stop(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    if ignored_in_undo(ctx, "STOP") {
        return Ok(None);
    }
    ctx.stop = super::StopKind::Stop;
    // `\AllMoveTasks`: the programs of the other running NORMAL tasks stop too (the
    // controller stops them). `\NoRegain` concerns a robot moved away while stopped,
    // which no one does here.
    ctx.resources.controller.stop_all_moves = present(args.get(1));
    Ok(None)
}

/// `ExitCycle`: ends the current cycle; the program pointer goes back to main. The
/// robot's movement stops and its paths are cleared; variables keep their values. In
/// continuous run mode the next cycle follows (`rapid run --cycles`), in cycle mode the
/// run ends.
pub(super) fn exit_cycle(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    super::exit_cycle_hooks(ctx)?;
    ctx.stop = super::StopKind::ExitCycle;
    Ok(None)
}

/// `Break` stops execution for debugging (no debugger is attached: like Stop); in UNDO
/// context it is ignored with an event-log warning (§1.13). (Break inside a loop ends
/// the loop: compiled as a jump, never called.)
pub(super) fn break_(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    if ignored_in_undo(ctx, "BREAK") {
        return Ok(None);
    }
    ctx.stop = super::StopKind::Stop;
    Ok(None)
}

/// In UNDO context `instruction` is not executed: logs the warning (the VM places it at
/// the call) and answers `true` (§1.13, `exec/undo.rs`).
fn ignored_in_undo(ctx: &mut Ctx<'_>, instruction: &str) -> bool {
    if !crate::exec::undo::in_undo_context(ctx.chain) {
        return false;
    }
    crate::exec::undo::log_ignored(ctx.events, ctx.time, instruction, ctx.routine, None);
    true
}

/// `BookErrNo ErrorName`: gives the errnum variable a free system error number.
pub(super) fn book_err_no(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let number = *ctx.next_booked;
    *ctx.next_booked += 1;
    ctx.store(&args[0], Value::Num(number as f32))?;
    Ok(None)
}

/// `Dim(ArrPar, DimNo)`: the size of dimension DimNo of an array.
pub(super) fn dim(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    let array = ctx.value(&args[0])?;
    let dim_no = ctx.num(&args[1])?;
    let Value::Array(array) = array else { return Err(ctx.error(Err::ArgValue, "Dim needs an array")) };
    let rank = f64::from(array.rank());
    if dim_no.fract() != 0.0 || dim_no < 1.0 || dim_no > rank {
        return Err(ctx.error(Err::OutOfBounds, format!("the array has no dimension {dim_no}")));
    }
    Ok(Some(Value::Num(array.dims[dim_no as usize - 1] as f32)))
}

/// Whether an INOUT argument refers to a persistent (a PERS, or through PERS params).
fn refers_to_pers(ctx: &Ctx<'_>, arg: &Value) -> bool {
    match arg {
        Value::Ref(place) => match place.root {
            crate::value::Root::Global(idx) => ctx.pers_globals.get(idx as usize).copied().unwrap_or(false),
            crate::value::Root::Stack(_) => false,
        },
        _ => false,
    }
}

/// `IsPers(DatObj)`: whether an INOUT parameter refers to a persistent.
pub(super) fn is_pers(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    Ok(Some(Value::Bool(refers_to_pers(ctx, &args[0]))))
}

/// `IsVar(DatObj)`: whether an INOUT parameter refers to a variable.
pub(super) fn is_var(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    Ok(Some(Value::Bool(!refers_to_pers(ctx, &args[0]))))
}

/// `RemainingRetries()`: how many more RETRYs the current error may take.
pub(super) fn remaining_retries(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    Ok(Some(Value::Num(ctx.retries_left as f32)))
}

/// `ResetRetryCount`: the retry count of the current error starts again.
pub(super) fn reset_retry_count(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    ctx.reset_retries = true;
    Ok(None)
}

/// `SkipWarn`: the error the running handler took leaves no warning in the event log.
pub(super) fn skip_warn(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    ctx.skip_warn = true;
    Ok(None)
}

/// `ExecHandler()`: which handler the calling routine is running (handler_type).
pub(super) fn exec_handler(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    let handler = ctx.chain.last().map_or(0, |frame| frame.handler_type());
    Ok(Some(Value::Num(f32::from(handler))))
}

/// `ExecLevel()`: LEVEL_TRAP (1) while a TRAP routine is anywhere in the call chain,
/// else LEVEL_NORMAL (0). Service routines (LEVEL_SERVICE, 2) do not exist here.
pub(super) fn exec_level(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    let in_trap = ctx.chain.iter().any(|frame| frame.is_trap());
    Ok(Some(Value::Num(if in_trap { 1.0 } else { 0.0 })))
}
