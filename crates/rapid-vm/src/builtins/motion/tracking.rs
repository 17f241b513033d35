//! The conveyor tracking instructions (WaitWObj, DropWObj) and what a move does when
//! its work object rides a conveyor (see `conveyor.rs` for the model).

use nalgebra::Vector3;

use super::super::{present, Ctx, StopKind};
use super::conveyor::Span;
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

type Res = Result<Option<Value>, RapidError>;

/// How long a wait with nothing scheduled sleeps before looking again (as WaitDI).
const IDLE_POLL: f64 = 3600.0;

/// Brings the conveyors up to the controller's time: inputs changed until now.
pub(super) fn refresh(ctx: &mut Ctx<'_>) {
    if ctx.resources.robot.conveyors.list.is_empty() {
        return;
    }
    ctx.resources.io.advance(ctx.time);
    let resources = &mut *ctx.resources;
    resources.robot.refresh_conveyors(resources.io.system.as_ref());
}

/// The conveyor a work object rides (`ufprog` FALSE, `ufmec` a conveyor's name), if
/// it does.
pub(super) fn conveyor_of(ctx: &Ctx<'_>, wobj: &Value) -> Option<usize> {
    let Value::Record(w) = wobj else { return None };
    match (w.fields.get(1), w.fields.get(2)) {
        (Some(Value::Bool(false)), Some(Value::Str(ufmec))) => ctx.resources.robot.conveyors.find(ufmec),
        _ => None,
    }
}

/// The conveyor of WaitWObj's and DropWObj's work object.
fn conveyor_arg(ctx: &Ctx<'_>, wobj: &Value) -> Result<usize, RapidError> {
    conveyor_of(ctx, &ctx.value(wobj)?)
        .ok_or_else(|| ctx.error(Err::CnvNotActive, "the work object rides no conveyor of the system (ufprog, ufmec)"))
}

/// `WaitWObj WObj [\RelDist] [\MaxTime] [\TimeFlag]`: connects the work object to the
/// first object in the conveyor's start window, waiting for one (with `\RelDist` until
/// it is that far from the sync switch). Connected already: ERR_CNV_CONNECT, unless
/// `\RelDist` is given (then it waits for the connected object to get that far).
pub(crate) fn wait_wobj(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refresh(ctx);
    let c = conveyor_arg(ctx, &args[0])?;
    let rel_dist = ctx.opt_num(args.get(1))?;
    let now = ctx.time;
    let conveyor = &mut ctx.resources.robot.conveyors.list[c];
    let object = match conveyor.connected {
        Some(_) if rel_dist.is_none() => {
            return Err(ctx.error(Err::CnvConnect, "the work object is connected already (DropWObj first)"));
        }
        Some(sync) => Some(sync),
        None => conveyor.first_in_window(now),
    };
    let reached = object.filter(|&sync| conveyor.position(now) - sync >= rel_dist.unwrap_or(f64::NEG_INFINITY));
    if reached.is_some() {
        if conveyor.connected.is_none() {
            conveyor.connect_first();
        }
        return end_wait(ctx, args, false);
    }
    // When the object gets far enough at today's speed (objects still to come arrive
    // with an input change, which ends the wait anyway).
    let arrival = object.and_then(|sync| conveyor.time_at_distance(sync, rel_dist.unwrap_or(0.0), now));
    keep_waiting(ctx, args, arrival)
}

/// The wait goes on until the next input change, the object's arrival or `\MaxTime`.
fn keep_waiting(ctx: &mut Ctx<'_>, args: &[Value], arrival: Option<f64>) -> Res {
    let now = ctx.time;
    let here = (ctx.chain.len(), ctx.chain.last().map_or(0, |f| f.position().1));
    let started = match ctx.resources.io.waiting {
        Some((depth, pc, at)) if (depth, pc) == here => at,
        _ => now,
    };
    let deadline = ctx.opt_num(args.get(2))?.map(|max| started + max);
    if deadline.is_some_and(|d| now >= d) {
        return end_wait(ctx, args, true);
    }
    ctx.resources.io.waiting = Some((here.0, here.1, started));
    let io_next = ctx.resources.io.next_event_time();
    let interrupt_next = super::super::interrupts::next_due(ctx);
    let next = [io_next, interrupt_next, arrival, deadline].into_iter().flatten().min_by(f64::total_cmp);
    let until = next.unwrap_or(now + IDLE_POLL).max(now);
    ctx.wait = Some((until - now).max(1e-6));
    ctx.stop = StopKind::Repeat;
    Ok(None)
}

/// The wait is over: connected, or (`timed_out`) `\MaxTime` ran out — with `\TimeFlag`
/// the flag says so, without it ERR_WAIT_MAXTIME.
fn end_wait(ctx: &mut Ctx<'_>, args: &[Value], timed_out: bool) -> Res {
    ctx.resources.io.waiting = None;
    if let Some(flag) = args.get(3).filter(|f| present(Some(f))) {
        ctx.store(flag, Value::Bool(timed_out))?;
        return Ok(None);
    }
    if timed_out {
        return Err(ctx.error(Err::WaitMaxTime, "no conveyor object came within \\MaxTime"));
    }
    Ok(None)
}

/// `DropWObj WObj`: the object is released (and gone from the queue). The robot must
/// have left the conveyor's work object (a move in a fixed one) first: otherwise the
/// motion stops (manual: DropWObj).
// uncertain: dropping a work object that is not connected is taken to do nothing.
pub(crate) fn drop_wobj(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refresh(ctx);
    let c = conveyor_arg(ctx, &args[0])?;
    let conveyors = &mut ctx.resources.robot.conveyors;
    if conveyors.open().is_some_and(|span| span.conveyor == c) {
        return Err(RapidError::fatal(
            "DropWObj while the robot still moves in the conveyor's work object: the motion stops \
             (move in a fixed work object first)",
        ));
    }
    conveyors.list[c].connected = None;
    Ok(None)
}

/// Before a move in work object `wobj`: a conveyor's work object starts the robot
/// following the object (its frames frozen where the object is then); a fixed one ends
/// a tracking under way. Returns the conveyor the move rides.
pub(super) fn begin_move(ctx: &mut Ctx<'_>, wobj: Option<&Value>) -> Result<Option<usize>, RapidError> {
    if ctx.resources.robot.conveyors.list.is_empty() {
        return Ok(None);
    }
    refresh(ctx);
    let c = wobj.and_then(|w| conveyor_of(ctx, w));
    let now = ctx.time;
    let open = ctx.resources.robot.conveyors.open().map(|s| s.conveyor);
    if open.is_some() && open != c {
        ctx.resources.robot.end_tracking(now);
    }
    let Some(c) = c else { return Ok(None) };
    let conveyor = &ctx.resources.robot.conveyors.list[c];
    let Some(distance) = conveyor.distance(now) else {
        return Err(ctx.error(Err::CnvNotActive, "the conveyor's work object is connected to no object (WaitWObj)"));
    };
    if distance > conveyor.config.max_dist {
        // uncertain: RobotWare's event for an object beyond its maximum distance is not in
        // our notes; execution stops.
        return Err(RapidError::fatal(format!(
            "the conveyor object is {distance:.1} mm from the sync switch, beyond the maximum distance {} mm",
            conveyor.config.max_dist
        )));
    }
    if open != Some(c) {
        ctx.resources.robot.start_tracking(c, now);
    }
    Ok(Some(c))
}

/// The user frame moves in conveyor `c`'s work object are planned in.
pub(super) fn planning_frame(ctx: &Ctx<'_>, c: usize) -> Option<rapid_motion::Pose> {
    let conveyors = &ctx.resources.robot.conveyors;
    let span = conveyors.open().filter(|s| s.conveyor == c)?;
    Some(conveyors.list[c].frame_at(span.d_ref))
}

/// While the robot follows a conveyor object: it must be able to reach where the
/// object takes it when the program goes on (`until`), else execution stops.
// uncertain: the controller's event for a tracked object leaving the robot's reach is
// not in our notes; the reach error (50050) is given.
pub(super) fn check_reach(robot: &mut super::robot::RobotState, until: f64) -> Result<(), RapidError> {
    if robot.conveyors.open().is_none() {
        return Ok(());
    }
    robot.joints_at(until);
    match robot.conveyors.unreachable.take() {
        Some(_) => Err(super::moves::motion_error(rapid_motion::MotionError::OutOfReach)),
        None => Ok(()),
    }
}

impl super::robot::RobotState {
    /// The robot starts following conveyor `c`'s connected object with its next move,
    /// which starts from a stop point.
    fn start_tracking(&mut self, c: usize, now: f64) {
        let t_ref = self.stop_here().max(now);
        let conveyor = &self.conveyors.list[c];
        let object = conveyor.connected.unwrap_or_default();
        let d_ref = conveyor.position(t_ref) - object;
        let dir = conveyor.config.base.rotation * Vector3::x();
        self.conveyors.spans.push(Span { conveyor: c, object, t_ref, d_ref, t_end: None, dir });
    }

    /// The robot stops following its conveyor object: where its last conveyor move
    /// (shifted by the object's travel) left it, at `now` or when it stops if later.
    fn end_tracking(&mut self, now: f64) {
        let t_end = self.stop_here().max(now);
        let joints = self.joints_at(t_end);
        if let Some(span) = self.conveyors.spans.last_mut() {
            span.t_end = Some(t_end);
        }
        // The next move starts from where the object took the robot.
        let eax = self.planner.end_eax();
        self.planner.restart_from(joints, t_end);
        self.planner.set_eax(eax);
        self.motion_end = t_end;
    }

    /// Ends the queue without a corner path failure: the waiting fly-by point becomes a
    /// stop point on purpose. Returns when the robot stands still.
    fn stop_here(&mut self) -> f64 {
        if let Some(mut last) = self.planner.flush() {
            last.corner_path_failure = false;
            self.finish(last);
        }
        self.motion_end
    }
}
