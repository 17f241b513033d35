//! StopMove, StartMove, IsStopMoveAct, ClearPath and PathLevel (§1.8, §2.2.6): the
//! robot stops on its path and later goes on with the rest of it (or ClearPath drops
//! the rest). While it stands, what was planned after the
//! stop (moves, path outputs, trigger interrupts, the program's wait for the robot)
//! is held, and on StartMove everything is moved on by the time it stood. TriggCheckIO
//! `\StopMove` and TriggStopProc stop the robot the same way ([`hold`]); TriggSpeed
//! outputs read 0 while it stands.

use super::super::{present, Ctx, Resources};
use crate::error::RapidError;
use crate::value::Value;

type Res = Result<Option<Value>, RapidError>;

/// What StopMove set aside until StartMove.
#[derive(Debug, Default, Clone)]
pub struct Pause {
    /// When the robot stopped.
    pub since: f64,
    /// The program's wait for the robot when it stopped.
    held_wait: Option<f64>,
    /// Path outputs and trigger interrupts after the stop: (time, …).
    held_orders: Vec<(f64, u32, f64)>,
    held_interrupts: Vec<(f64, u32)>,
    /// TriggSpeed outputs set to 0 while the robot stands, with their values.
    speed_outputs: Vec<(u32, f64)>,
}

fn refuse_all_tasks(args: &[Value], idx: usize) -> Result<(), RapidError> {
    if present(args.get(idx)) {
        return Err(RapidError::fatal("\\AllMotionTasks is not supported by `rapid run` yet"));
    }
    Ok(())
}

/// `StopMove [\Quick] [\AllMotionTasks]`: the robot stops where it is.
// uncertain: the stopping distance (a path stop decelerates, \Quick faster) is not
// modelled: the robot stands at the place it was at the instant of StopMove.
pub(crate) fn stop_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse_all_tasks(args, 1)?;
    hold(ctx.resources, ctx.time);
    Ok(None)
}

/// The robot stops on its path at `now` (StopMove, TriggCheckIO `\StopMove`): what was
/// planned after it is held until StartMove. Nothing changes when it is stopped already.
pub(crate) fn hold(resources: &mut Resources, now: f64) {
    if resources.robot.pause.is_some() {
        return;
    }
    let held_wait = resources.robot.hold_until.map(|_| f64::INFINITY);
    let held_wait = std::mem::replace(&mut resources.robot.hold_until, held_wait);
    let orders = &mut resources.io.path_orders;
    let split = orders.partition_point(|&(t, _, _)| t <= now);
    let held_orders = orders.split_off(split).into_iter().collect();
    let scheduled = &mut resources.interrupts.scheduled;
    let held_interrupts = scheduled.iter().copied().filter(|&(t, _)| t > now).collect();
    scheduled.retain(|&(t, _)| t <= now);
    // A TriggSpeed output follows the TCP speed: 0 while the robot stands.
    let mut speed_outputs = Vec::new();
    resources.io.advance(now);
    if let Some(io) = resources.io.system.as_mut() {
        for signal in resources.robot.trigg.speed_outputs_after(now) {
            speed_outputs.push((signal, io.value(signal).unwrap_or(0.0)));
            let _ = io.set(signal, 0.0, now);
        }
    }
    resources.robot.pause = Some(Pause { since: now, held_wait, held_orders, held_interrupts, speed_outputs });
}

/// `StartMove [\AllMotionTasks]`: the robot goes on along its path.
pub(crate) fn start_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refuse_all_tasks(args, 0)?;
    let Some(pause) = ctx.resources.robot.pause.take() else { return Ok(None) };
    let now = ctx.time;
    let dt = (now - pause.since).max(0.0);
    ctx.resources.robot.resume_after(pause.since, dt);
    ctx.resources.robot.hold_until = pause.held_wait.map(|t| t + dt);
    if let Some(until) = ctx.resources.robot.hold_until {
        // The executor looks at the program's wait for the robot before each
        // instruction only while an interrupt may come: a scheduled interrupt of number
        // 0 (none has it) keeps it looking until the wait ends, also when StartMove ran
        // in a trap of an interrupt that has no source (TriggInt, TriggCheckIO).
        ctx.resources.interrupts.schedule(until, 0);
    }
    for (signal, value) in pause.speed_outputs {
        ctx.resources.io.order_on_path(now, signal, value);
    }
    for (t, signal, value) in pause.held_orders {
        ctx.resources.io.order_on_path(t + dt, signal, value);
    }
    for (t, number) in pause.held_interrupts {
        ctx.resources.interrupts.schedule(t + dt, number);
    }
    Ok(None)
}

/// `IsStopMoveAct([\FromMoveTask] | [\FromNonMoveTask])`: whether StopMove holds the
/// robot.
// uncertain: both flags answer the one stop state of the task's robot.
pub(crate) fn is_stop_move_act(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Bool(ctx.resources.robot.pause.is_some())))
}

/// `ClearPath`: the rest of the robot's path is dropped: it stays where it is (where
/// StopMove stopped it); the move instruction the program waits on ends, and its path
/// outputs and trigger interrupts not yet due never come.
// uncertain: with the robot moving (no StopMove first) the path is cleared at once,
// without a braking distance.
pub(crate) fn clear_path(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let now = ctx.time;
    let since = ctx.resources.robot.pause.as_ref().map_or(now, |p| p.since);
    ctx.resources.robot.stop_at(since);
    ctx.resources.robot.due.retain(|&(t, _)| t <= since);
    ctx.resources.robot.trigg.pending.retain(|&(t, _)| t <= since);
    ctx.resources.robot.trigg.runs.clear();
    // TriggSpeed outputs end with the path: 0, as the robot stands.
    let speed_outputs = ctx.resources.robot.trigg.speed_outputs_after(since);
    ctx.resources.robot.trigg.speed_outputs.clear();
    ctx.resources.io.advance(now);
    if let Some(io) = ctx.resources.io.system.as_mut() {
        for signal in speed_outputs {
            let _ = io.set(signal, 0.0, now);
        }
    }
    if let Some(pause) = ctx.resources.robot.pause.as_mut() {
        pause.held_orders.clear();
        pause.held_interrupts.clear();
        pause.speed_outputs.clear();
        // The program's wait for the dropped move ends as soon as the robot may move.
        pause.held_wait = pause.held_wait.map(|_| since);
    } else {
        ctx.resources.robot.hold_until = None;
        let orders = &mut ctx.resources.io.path_orders;
        orders.retain(|&(t, _, _)| t <= now);
        ctx.resources.interrupts.scheduled.retain(|&(t, _)| t <= now);
    }
    Ok(None)
}

/// `PathLevel()`: 1, the base level; StorePath (level 2) is not run yet (a program
/// using it is refused at load), so no other level exists.
pub(crate) fn path_level(_ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Num(1.0)))
}
