//! StopMove, StartMove, StartMoveRetry, StopMoveReset, IsStopMoveAct, ClearPath and
//! PathLevel (§1.8, §2.2.6): the robot stops on its path and later goes on with the
//! rest of it (or ClearPath drops the rest). While it stands, what was planned after
//! the stop (moves, path outputs, trigger interrupts, the program's wait for the
//! robot) is held, and on StartMove everything is moved on by the time it stood.
//! After StorePath/RestoPath (store.rs) the robot may stand elsewhere: StartMove
//! first takes it back to where the path stopped (regain), or refuses when that is
//! too far. TriggCheckIO `\StopMove` and TriggStopProc stop the robot the same way
//! ([`hold`]); TriggSpeed outputs read 0 while it stands.

use crate::RobotResources;
use rapid_motion::plan::{AccelLimits, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData};
use rapid_motion::{Joints, Kinematics};

use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, Err, RapidError, Resources, StopKind, Value};

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
    /// Where the stopped path goes on, when the robot may stand elsewhere (after
    /// RestoPath): StartMove takes it back there first.
    pub(super) regain: Option<Joints>,
    /// StopMoveReset cleared the stop-move state: the path stays stopped until a
    /// program start (or StartMove), but IsStopMoveAct is FALSE.
    reset: bool,
    /// TriggSpeed outputs set to 0 while the robot stands, with their values.
    speed_outputs: Vec<(u32, f64)>,
    /// StepBwdPath's steps back from where the path stopped (a RESTART routine).
    pub(super) step: Option<super::stepbwd::StepBack>,
}

impl Pause {
    /// Whether the stop-move state is set (StopMove, not reset by StopMoveReset).
    pub(super) fn flagged(&self) -> bool {
        !self.reset
    }

    /// The path stopped without the stop-move state (StorePath without StopMove).
    pub(super) fn unflagged(self) -> Pause {
        Pause { reset: true, ..self }
    }

    /// The same stop `dt` seconds later: RestoPath holds the base path until the
    /// moves of path level 2 are done.
    pub(super) fn delay(&mut self, dt: f64) {
        self.since += dt;
        self.held_wait = self.held_wait.map(|t| t + dt);
        self.held_orders.iter_mut().for_each(|o| o.0 += dt);
        self.held_interrupts.iter_mut().for_each(|i| i.0 += dt);
    }
}

/// How far the robot may stand from its stopped path for StartMove to take it back:
/// farther gives ERR_PATHDIST.
// uncertain: the manual's figures as we remember them (10 mm or 20 degrees).
pub(super) const REGAIN_MAX_MM: f64 = 10.0;
pub(super) const REGAIN_MAX_DEG: f64 = 20.0;

/// The speed of the move back to the path.
// uncertain: the controller's regain speed is not published; a slow v100.
const REGAIN_SPEED: f64 = 100.0;

/// `\AllMotionTasks`: the other motion tasks' robots get the same instruction first,
/// through the controller. `false` while the answer is awaited (the instruction runs
/// again); `true` when this task's own robot may follow (or the switch is absent).
// uncertain: the other robots are stopped or started at the instant the instruction
// runs, as one StopMove/StartMove of their own would.
fn all_motion_tasks(ctx: &mut Ctx<'_>, args: &[Value], idx: usize, name: &'static str) -> bool {
    if !present(args.get(idx)) {
        return true;
    }
    rapid_vm::ext::ask(ctx, rapid_vm::ext::Request::AllMotionTasks { name }).is_some()
}

/// The robot's path stops at `since` (now for StopMove; the end of the move it is on
/// for a StorePath without StopMove): path outputs and trigger interrupts after it
/// and the program's wait for the robot are held.
pub(super) fn pause_at(ctx: &mut Ctx<'_>, since: f64) -> Result<Pause, RapidError> {
    let robot = ctx.resources.robot_mut();
    if robot.planner.has_pending() && robot.planner.time() <= since {
        // The robot is on a move still waiting for its successor (after \Conc): it
        // becomes final, ending in a stop point, so it can be stopped on.
        // uncertain: a fly-by point there becomes a stop point (the path is stopped).
        robot.flush();
        // Its path outputs become orders, which are held below like the others.
        super::moves::apply_due_events(ctx)?;
    }
    Ok(hold_after(ctx.resources, since))
}

/// Holds what was planned after `since`: path outputs and trigger interrupts, the
/// program's wait for the robot; TriggSpeed outputs go to 0 (the robot stands).
fn hold_after(resources: &mut Resources, since: f64) -> Pause {
    let held_wait = resources.robot_mut().hold_until.map(|_| f64::INFINITY);
    let held_wait = std::mem::replace(&mut resources.robot_mut().hold_until, held_wait);
    let orders = &mut resources.io_mut().path_orders;
    let split = orders.partition_point(|&(t, _, _)| t <= since);
    let held_orders = orders.split_off(split).into_iter().collect();
    let scheduled = &mut resources.interrupts.scheduled;
    let held_interrupts = scheduled.iter().copied().filter(|&(t, _)| t > since).collect();
    scheduled.retain(|&(t, _)| t <= since);
    let mut speed_outputs = Vec::new();
    resources.io_mut().advance(since);
    let speed_signals = resources.robot().trigg.speed_outputs_after(since);
    if let Some(io) = resources.io_mut().system.as_mut() {
        for signal in speed_signals {
            speed_outputs.push((signal, io.value(signal).unwrap_or(0.0)));
            let _ = io.set(signal, 0.0, since);
        }
    }
    Pause { since, held_wait, held_orders, held_interrupts, regain: None, reset: false, speed_outputs, step: None }
}

/// `StopMove [\Quick] [\AllMotionTasks]`: the robot stops where it is.
// uncertain: the stopping distance (a path stop decelerates, \Quick faster) is not
// modelled: the robot stands at the place it was at the instant of StopMove.
pub(crate) fn stop_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if !all_motion_tasks(ctx, args, 1, "StopMove") {
        return Ok(None);
    }
    if let Some(pause) = ctx.resources.robot_mut().pause.as_mut() {
        // Stopped already: the stop-move state is set again (after StopMoveReset).
        pause.reset = false;
        return Ok(None);
    }
    let pause = pause_at(ctx, ctx.time)?;
    ctx.resources.robot_mut().pause = Some(pause);
    Ok(None)
}

/// The robot stops on its path at `now` (TriggCheckIO `\StopMove`, TriggStopProc): what
/// was planned after it is held until StartMove. Nothing changes when it is stopped
/// already.
pub(crate) fn hold(resources: &mut Resources, now: f64) {
    if resources.robot_mut().pause.is_none() {
        resources.robot_mut().pause = Some(hold_after(resources, now));
    }
}

/// `StartMove [\AllMotionTasks]`: the robot goes on along its path.
pub(crate) fn start_move(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if !all_motion_tasks(ctx, args, 0, "StartMove") {
        return Ok(None);
    }
    restart(ctx)?;
    Ok(None)
}

/// `StartMoveRetry`: StartMove, then RETRY of the instruction whose error the ERROR
/// handler takes (outside an ERROR handler RETRY's own error stops the program).
pub(crate) fn start_move_retry(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    restart(ctx)?;
    ctx.stop = StopKind::Retry;
    Ok(None)
}

/// `StopMoveReset [\AllMotionTasks]`: the stop-move state is reset without starting
/// any movement (the manual): the stopped path goes on at the next program start, or
/// with StartMove. `rapid run` starts the program once, so until StartMove the robot
/// stands; what StopMoveReset changes is IsStopMoveAct, and that StorePath, level 2
/// and ClearPath work from the stopped state as after StopMove.
// uncertain: the manual's "restart at the next program start" read for a run that
// is never stopped and started again.
pub(crate) fn stop_move_reset(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if !all_motion_tasks(ctx, args, 0, "StopMoveReset") {
        return Ok(None);
    }
    if let Some(pause) = ctx.resources.robot_mut().pause.as_mut() {
        pause.reset = true;
    }
    Ok(None)
}

/// Ends the stop: the path goes on now (after a move back to it if the robot
/// stands elsewhere). Errors: ERR_ALRDY_MOVING when the robot moves and was not
/// stopped, ERR_PATHDIST when it stands too far from its path.
fn restart(ctx: &mut Ctx<'_>) -> Result<(), RapidError> {
    let now = ctx.time;
    let Some(pause) = ctx.resources.robot_mut().pause.take() else {
        // uncertain: "moving" is taken as having planned motion not yet done.
        let robot = ctx.resources.robot_mut();
        if robot.motion_end > now || robot.planner.has_pending() {
            return Err(ctx.error(Err::AlreadyMoving, "the robot is already moving (no StopMove to undo)"));
        }
        return Ok(());
    };
    let regain = match pause.regain {
        Some(path) => regain_move(ctx, &pause, path),
        None => Ok(None),
    };
    let regain = match regain {
        Ok(regain) => regain,
        Err(err) => {
            ctx.resources.robot_mut().pause = Some(pause);
            return Err(err);
        }
    };
    // After StepBwdPath the robot goes forward to where it stopped first.
    let forward = match pause.step.as_ref().map(|step| super::stepbwd::forward(ctx, &pause, step)) {
        Some(Err(err)) => {
            ctx.resources.robot_mut().pause = Some(pause);
            return Err(err);
        }
        Some(Ok(forward)) => Some(forward),
        None => None,
    };
    let back = regain.as_ref().map_or(0.0, PlannedMove::duration) + forward.as_ref().map_or(0.0, PlannedMove::duration);
    let dt = (now - pause.since).max(0.0) + back;
    let robot = ctx.resources.robot_mut();
    robot.resume_after(pause.since, dt);
    if let Some(regain) = regain {
        insert_in_time(robot, regain);
    }
    if let (Some(step), Some(forward)) = (pause.step, forward) {
        super::stepbwd::splice(robot, pause.since, step, forward);
    }
    robot.hold_until = pause.held_wait.map(|t| t + dt);
    for (signal, value) in pause.speed_outputs {
        ctx.resources.io_mut().order_on_path(now, signal, value);
    }
    for (t, signal, value) in pause.held_orders {
        ctx.resources.io_mut().order_on_path(t + dt, signal, value);
    }
    for (t, number) in pause.held_interrupts {
        ctx.resources.interrupts.schedule(t + dt, number);
    }
    Ok(())
}

/// The move from where the robot stands back to `path`, starting now; None when it
/// stands there already. ERR_PATHDIST when that is farther than the regain limit.
fn regain_move(ctx: &mut Ctx<'_>, pause: &Pause, path: Joints) -> Result<Option<PlannedMove>, RapidError> {
    let settings = super::moves::planner_settings(ctx);
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    let here = robot.joints_at(pause.since);
    let (tool, held_object) = super::moves::mount_of(&robot.active);
    let (a, b) = (robot.kin.forward(&here) * tool, robot.kin.forward(&path) * tool);
    let mm = (a.translation.vector - b.translation.vector).norm();
    let deg = a.rotation.angle_to(&b.rotation).to_degrees();
    if mm > REGAIN_MAX_MM || deg > REGAIN_MAX_DEG {
        return Err(ctx.error(
            Err::PathDist,
            format!("the robot stands {mm:.1} mm, {deg:.1}° from its stopped path (at most {REGAIN_MAX_MM} mm, {REGAIN_MAX_DEG}°)"),
        ));
    }
    if mm < 1e-3 && deg < 1e-3 {
        return Ok(None);
    }
    let mut planner = Planner::new(here, AccelLimits::nominal(&robot.model.max_speeds));
    planner.set_settings(settings);
    planner.idle_until(now.max(pause.since));
    let speed = SpeedData { v_tcp: REGAIN_SPEED, ..SpeedData::VMAX };
    let wobj = super::moves::wobj_frame(&robot.active);
    let request = MoveRequest { target: Target::Joints(path), speed, zone: ZoneData::FINE, tool, held_object, wobj };
    let planned = planner.push(&robot.kin, &request).map_err(super::moves::motion_error)?;
    // The arm alone goes back: the external axes stand where they stopped.
    let eax = robot.eax_at(pause.since);
    Ok(planned.or_else(|| planner.flush()).map(|mut planned| {
        planned.hold_eax(eax);
        planned
    }))
}

/// Puts a move in the robot's queue (and the trace) by its start time.
pub(super) fn insert_in_time(robot: &mut super::robot::RobotState, planned: PlannedMove) {
    let at = robot.ahead.iter().position(|m| m.start >= planned.end).unwrap_or(robot.ahead.len());
    if let Some(recorded) = &mut robot.recorded {
        let i = recorded.iter().position(|m| m.start >= planned.end).unwrap_or(recorded.len());
        recorded.insert(i, planned.clone());
    }
    robot.ahead.insert(at, planned);
}

/// `IsStopMoveAct([\FromMoveTask] | [\FromNonMoveTask])`: whether the stop-move
/// state is set: StopMove, not yet undone by StartMove or StopMoveReset (on path
/// level 2 the stored base path's state).
// uncertain: both flags answer the one stop state of the task's robot, and the
// state of the stored path counts on level 2.
pub(crate) fn is_stop_move_act(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let robot = ctx.resources.robot_mut();
    let stored = robot.stored.as_ref().is_some_and(|s| s.stop_move_act());
    Ok(Some(Value::Bool(robot.pause.as_ref().is_some_and(Pause::flagged) || stored)))
}

/// `ClearPath`: the rest of the robot's path is dropped: it stays where it is (where
/// StopMove stopped it); the move instruction the program waits on ends, and its path
/// outputs and trigger interrupts not yet due never come.
// uncertain: with the robot moving (no StopMove first) the path is cleared at once,
// without a braking distance.
pub(crate) fn clear_path(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let now = ctx.time;
    let since = ctx.resources.robot_mut().pause.as_ref().map_or(now, |p| p.since);
    if ctx.resources.robot_mut().pause.as_ref().is_some_and(|p| p.regain.is_some()) {
        // After RestoPath the base path starts where path level 2 ended: drop it
        // whole, so the robot stays where level 2 left it.
        super::store::drop_from(ctx.resources.robot_mut(), since);
    }
    ctx.resources.robot_mut().stop_at(since);
    ctx.resources.robot_mut().due.retain(|&(t, _)| t <= since);
    ctx.resources.robot_mut().trigg.pending.retain(|&(t, _)| t <= since);
    ctx.resources.robot_mut().trigg.runs.clear();
    // TriggSpeed outputs end with the path: 0, as the robot stands.
    let speed_outputs = ctx.resources.robot_mut().trigg.speed_outputs_after(since);
    ctx.resources.robot_mut().trigg.speed_outputs.clear();
    ctx.resources.io_mut().advance(now);
    if let Some(io) = ctx.resources.io_mut().system.as_mut() {
        for signal in speed_outputs {
            let _ = io.set(signal, 0.0, now);
        }
    }
    if let Some(pause) = ctx.resources.robot_mut().pause.as_mut() {
        pause.held_orders.clear();
        pause.held_interrupts.clear();
        pause.speed_outputs.clear();
        // The program's wait for the dropped move ends as soon as the robot may move.
        pause.held_wait = pause.held_wait.map(|_| since);
        // Nothing is left to go back to.
        pause.regain = None;
    } else {
        ctx.resources.robot_mut().hold_until = None;
        let orders = &mut ctx.resources.io_mut().path_orders;
        orders.retain(|&(t, _, _)| t <= now);
        ctx.resources.interrupts.scheduled.retain(|&(t, _)| t <= now);
    }
    Ok(None)
}

/// ExitCycle in a motion task: the robot stops where it is and every path, on both
/// path levels, is cleared (as StopMove, ClearPath and StartMove would, with the stored
/// base path dropped), so the next cycle starts from where the robot stands.
// uncertain: the manual's "on-going robot movements stop" taken as an immediate stop,
// as StopMove's.
pub(crate) fn abandon_paths(ctx: &mut Ctx<'_>) -> Result<(), RapidError> {
    if rapid_tasks::my_task(ctx).is_some_and(|t| !t.motion) {
        return Ok(());
    }
    ctx.resources.robot_mut().stored = None;
    stop_move(ctx, &[])?;
    clear_path(ctx, &[])?;
    restart(ctx)
}

/// `PathLevel()`: 1 on the base path, 2 after StorePath (until RestoPath).
pub(crate) fn path_level(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Num(if ctx.resources.robot_mut().stored.is_some() { 2.0 } else { 1.0 })))
}
