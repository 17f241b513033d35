//! The conveyor tracking instructions (WaitWObj, DropWObj) and what a move does when
//! its work object rides a conveyor (see `conveyor.rs` for the model).

use super::conveyor::{Fade, Mover, Span};
use crate::RobotResources;
use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// Brings the conveyors up to the controller's time: inputs changed until now.
pub(super) fn refresh(ctx: &mut Ctx<'_>) {
    if ctx.resources.robot_mut().following.conveyors.is_empty() {
        return;
    }
    ctx.resources.io_mut().advance(ctx.time);
    // The robot's state and the I/O's share the extension slot: the signals are
    // lent out for the look.
    let system = ctx.resources.io_mut().system.take();
    super::robot_in(&mut ctx.resources.extensions).refresh_conveyors(system.as_ref());
    ctx.resources.io_mut().system = system;
}

/// What carries a work object that moves: a conveyor, an external unit, or an external
/// unit of another task (indexes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Carrier {
    Conveyor(usize),
    Unit(usize),
    Foreign(usize),
}

impl Carrier {
    fn of(mover: &Mover) -> Carrier {
        match *mover {
            Mover::Conveyor { conveyor, .. } => Carrier::Conveyor(conveyor),
            Mover::Unit { unit, .. } => Carrier::Unit(unit),
            Mover::Foreign { unit, .. } => Carrier::Foreign(unit),
        }
    }
}

/// The `ufmec` of a work object that moves with a mechanical unit (`ufprog` FALSE).
pub(super) fn ufmec(wobj: &Value) -> Option<&str> {
    let Value::Record(w) = wobj else { return None };
    match (w.fields.get(1), w.fields.get(2)) {
        (Some(Value::Bool(false)), Some(Value::Str(ufmec))) => Some(ufmec),
        _ => None,
    }
}

/// The conveyor a work object rides (`ufprog` FALSE, `ufmec` a conveyor's name), if
/// it does.
pub(super) fn conveyor_of(ctx: &Ctx<'_>, wobj: &Value) -> Option<usize> {
    ctx.resources.robot().following.find(ufmec(wobj)?)
}

/// The conveyor of WaitWObj's and DropWObj's work object.
fn conveyor_arg(ctx: &Ctx<'_>, wobj: &Value) -> Result<usize, RapidError> {
    conveyor_of(ctx, &ctx.value(wobj)?)
        .ok_or_else(|| ctx.error(Err::CnvNotActive, "the work object rides no conveyor of the system (ufprog, ufmec)"))
}

/// What carries a work object: a conveyor, or an external unit with a frame; `None` for
/// a fixed work object (or one no unit of the system carries).
pub(super) fn carrier_of(ctx: &Ctx<'_>, wobj: &Value) -> Result<Option<Carrier>, RapidError> {
    let Some(name) = ufmec(wobj) else { return Ok(None) };
    let robot = ctx.resources.robot();
    if let Some(c) = robot.following.find(name) {
        return Ok(Some(Carrier::Conveyor(c)));
    }
    if let Some(f) = robot.external.find_foreign(name) {
        return Ok(Some(Carrier::Foreign(f)));
    }
    let Some(u) = robot.external.find(name) else { return Ok(None) };
    unit_mover(robot, u)?;
    Ok(Some(Carrier::Unit(u)))
}

/// What moves `carrier`'s work object, as the robot follows it.
pub(super) fn mover_of(ctx: &Ctx<'_>, carrier: Carrier) -> Result<Mover, RapidError> {
    let robot = ctx.resources.robot();
    Ok(match carrier {
        Carrier::Conveyor(c) => {
            Mover::Conveyor { conveyor: c, object: robot.following.conveyors[c].connected.unwrap_or_default() }
        }
        Carrier::Unit(u) => unit_mover(robot, u)?,
        Carrier::Foreign(f) => Mover::Foreign { unit: f, chain: robot.external.foreign[f].chain },
    })
}

/// How external unit `u` carries a work object: its axes, in order, from its frame.
pub(super) fn unit_mover(robot: &super::robot::RobotState, u: usize) -> Result<Mover, RapidError> {
    let unit = &robot.external.units[u].unit;
    match unit.chain() {
        Some(chain) => Ok(Mover::Unit { unit: u, chain }),
        None => Err(RapidError::fatal(format!(
            "unit {} has no frame (base, orientation) to carry a work object (ufmec)",
            unit.name
        ))),
    }
}

/// `WaitWObj WObj [\RelDist] [\MaxTime] [\TimeFlag]`: connects the work object to the
/// first object in the conveyor's start window, waiting for one (with `\RelDist` until
/// it is that far from the sync switch). Connected already: ERR_CNV_CONNECT, unless
/// `\RelDist` is given (then it waits for the connected object to get that far).
pub(crate) fn wait_wobj(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    refresh(ctx);
    let c = conveyor_arg(ctx, &args[0])?;
    check_active(ctx, c)?;
    let rel_dist = ctx.opt_num(args.get(1))?;
    let now = ctx.time;
    let conveyor = &mut ctx.resources.robot_mut().following.conveyors[c];
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
    let started = rapid_vm::ext::wait_started(ctx);
    let deadline = ctx.opt_num(args.get(2))?.map(|max| started + max);
    if deadline.is_some_and(|d| ctx.time >= d) {
        return end_wait(ctx, args, true);
    }
    rapid_vm::ext::wait_again(ctx, started, deadline, arrival);
    Ok(None)
}

/// The wait is over: connected, or (`timed_out`) `\MaxTime` ran out — with `\TimeFlag`
/// the flag says so, without it ERR_WAIT_MAXTIME.
fn end_wait(ctx: &mut Ctx<'_>, args: &[Value], timed_out: bool) -> Res {
    ctx.resources.end_wait();
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
    let following = &mut ctx.resources.robot_mut().following;
    if following.open().is_some_and(|span| Carrier::of(&span.mover) == Carrier::Conveyor(c)) {
        return Err(RapidError::fatal(
            "DropWObj while the robot still moves in the conveyor's work object: the motion stops \
             (move in a fixed work object first)",
        ));
    }
    following.conveyors[c].connected = None;
    Ok(None)
}

/// Before a move in work object `wobj`: a moving work object (on a conveyor or an
/// external unit) starts the robot following it (its frames frozen where it is then); a
/// fixed one ends a following under way. Returns what carries the move's work object.
pub(super) fn begin_move(ctx: &mut Ctx<'_>, wobj: Option<&Value>) -> Result<Option<Carrier>, RapidError> {
    let robot = ctx.resources.robot_mut();
    robot.next_foreign = None;
    let idle = robot.following.conveyors.is_empty() && robot.following.open().is_none();
    if idle && robot.external.units.iter().all(|u| u.unit.frame.is_none()) && robot.external.foreign.is_empty() {
        return Ok(None);
    }
    refresh(ctx);
    let mut carrier = match wobj {
        Some(w) => carrier_of(ctx, w)?,
        None => None,
    };
    if let Some(Carrier::Foreign(f)) = carrier {
        // Semi-coordinated, the object stands where its unit has it: a fixed frame.
        if !super::foreign::follows(ctx, f)? {
            carrier = None;
        }
        ctx.resources.robot_mut().next_foreign = Some(f);
    }
    let now = ctx.time;
    let open = ctx.resources.robot_mut().following.open().map(|s| Carrier::of(&s.mover));
    if open.is_some() && open != carrier {
        let robot = ctx.resources.robot_mut();
        if carrier.is_some() || !robot.blend_exit(now) {
            robot.end_tracking(now);
        }
    }
    let Some(carrier) = carrier else { return Ok(None) };
    if let Carrier::Conveyor(c) = carrier {
        check_object(ctx, c)?;
    }
    if open != Some(carrier) {
        let mover = mover_of(ctx, carrier)?;
        ctx.resources.robot_mut().start_tracking(mover, now);
    }
    Ok(Some(carrier))
}

/// Synchronized movement ended: a robot following another task's unit stops following
/// it (where its last move in the unit's work object leaves it, once it stands).
pub(crate) fn stop_following_other_tasks(ctx: &mut Ctx<'_>) {
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    if robot.following.open().is_some_and(|span| matches!(span.mover, Mover::Foreign { .. })) {
        robot.end_tracking(now);
    }
}

/// Conveyor `c`'s mechanical unit must be active (ActUnit) to track.
fn check_active(ctx: &Ctx<'_>, c: usize) -> Result<(), RapidError> {
    let name = &ctx.resources.robot().following.conveyors[c].config.name;
    match ctx.resources.robot().external.is_active(name) {
        Some(false) => Err(ctx.error(Err::CnvNotActive, format!("the conveyor {name} is not active (ActUnit)"))),
        _ => Ok(()),
    }
}

/// A move on conveyor `c`'s object: its unit must be active, the object connected and
/// within the maximum distance.
fn check_object(ctx: &Ctx<'_>, c: usize) -> Result<(), RapidError> {
    check_active(ctx, c)?;
    let conveyor = &ctx.resources.robot().following.conveyors[c];
    let Some(distance) = conveyor.distance(ctx.time) else {
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
    Ok(())
}

/// The user frame moves in `carrier`'s work object are planned in.
pub(super) fn planning_frame(ctx: &Ctx<'_>, carrier: Carrier) -> Option<rapid_motion::Pose> {
    let following = &ctx.resources.robot().following;
    let span = following.open().filter(|s| Carrier::of(&s.mover) == carrier)?;
    Some(span.mover.user_frame(&following.conveyors, &span.at_ref))
}

/// The active work object's user frame at controller time `t`: while the robot follows
/// a moving work object, the frame the moves were planned in, carried to where the
/// object is at `t`.
pub(super) fn active_uframe_at(robot: &super::robot::RobotState, t: f64) -> rapid_motion::Pose {
    let uframe = robot.active.uframe;
    let Some(span) = robot.following.open() else {
        // A work object another task's unit carries is where that unit has it now.
        let foreign = robot.active_foreign.and_then(|f| Some((robot.external.foreign.get(f)?, f)));
        return foreign
            .map_or(uframe, |(unit, f)| unit.chain.frame_at(&robot.foreign_eax_at(f, t).unwrap_or_default()));
    };
    let at = robot.mover_at(&span.mover, t, |t| robot.eax_at(t)).unwrap_or(span.at_ref);
    span.mover.carry(&robot.following.conveyors, &span.at_ref, &at) * uframe
}

/// While the robot follows a conveyor object: it must be able to reach where the
/// object takes it when the program goes on (`until`), else execution stops.
// uncertain: the controller's event for a tracked object leaving the robot's reach is
// not in our notes; the reach error (50050) is given.
pub(super) fn check_reach(robot: &mut super::robot::RobotState, until: f64) -> Result<(), RapidError> {
    if robot.following.open().is_none() {
        return Ok(());
    }
    robot.joints_at(until);
    match robot.following.unreachable.take() {
        Some(_) => Err(super::moves::motion_error(rapid_motion::MotionError::OutOfReach)),
        None => Ok(()),
    }
}

impl super::robot::RobotState {
    /// The robot starts following the work object `mover` carries with its next move.
    /// From a stop point (or a fly-by point given too late) the frames are frozen where
    /// the robot stands. From a fly-by point in a fixed work object there is no stop
    /// (§2.2.3: the change to coordinated motion gets a joint-interpolated corner, as
    /// any change of work object): the frames are frozen where the object will be when
    /// the robot would stand at that point, and the following fades in over the corner.
    // uncertain: how the controller joins the moving object on the corner.
    fn start_tracking(&mut self, mover: Mover, now: f64) {
        let from_fixed = self.following.open().is_none();
        let blend = self.planner.pending_stop_time().filter(|&stop| from_fixed && now <= stop);
        if let Some(stop) = blend {
            let at_ref = self.mover_at(&mover, stop, |t| self.eax_at(t)).unwrap_or_default();
            let span = Span {
                mover,
                t_ref: now,
                at_ref,
                t_end: None,
                fade: Fade::Pending,
                exit: Fade::None,
                frames_ref: at_ref,
            };
            self.following.spans.push(span);
            return;
        }
        let t_ref = self.stop_here().max(now);
        let at_ref = self.mover_at(&mover, t_ref, |t| self.eax_at(t)).unwrap_or_default();
        let span = Span { mover, t_ref, at_ref, t_end: None, fade: Fade::None, exit: Fade::None, frames_ref: at_ref };
        self.following.spans.push(span);
    }

    /// From a fly-by point on a conveyor object into a move in a fixed work object given
    /// in time: no stop (§2.2.3: the change from coordinated motion gets a corner path).
    /// The waiting move is rebased to where the object will be when the robot would
    /// stand at its point, so the next move is planned from there in the world and the
    /// two share a corner; the rebased move is carried by the object's travel from that
    /// place, fading out over the corner (`Span::exit`). False when that cannot be (no
    /// waiting move, given too late, the rebased path out of reach, a turn of a move
    /// entered through a reorientation zone): the caller stops following as before.
    // uncertain: how the controller leaves a moving object on the corner.
    pub(super) fn blend_exit(&mut self, now: f64) -> bool {
        let Some(stop) = self.planner.pending_stop_time().filter(|&stop| now <= stop) else { return false };
        let Some(span) = self.following.open().filter(|s| s.exit == Fade::None) else { return false };
        let (mover, frames_ref, at_ref) = (span.mover, span.frames_ref, span.at_ref);
        let Some(at_end) = self.mover_at(&mover, stop, |t| self.eax_at(t)) else { return false };
        let world = mover.carry(&self.following.conveyors, &at_ref, &at_end);
        let by = self.base_frame.inverse() * world * self.base_frame;
        let starts = self.planner.time();
        if self.planner.rebase_pending(&self.kin, &by).is_err() {
            return false;
        }
        // The moves before the waiting one stay in the span as it was; the waiting one
        // gets a span of its own, carried from where it was rebased to.
        if let Some(old) = self.following.spans.last_mut() {
            old.t_end = Some(starts);
        }
        let exit = Fade::Pending;
        let span = Span { mover, t_ref: starts, at_ref: at_end, t_end: None, fade: Fade::None, exit, frames_ref };
        self.following.spans.push(span);
        true
    }

    /// The robot stops following its conveyor object: where its last conveyor move
    /// (shifted by the object's travel) left it, at `now` or when it stops if later.
    fn end_tracking(&mut self, now: f64) {
        let t_end = self.stop_here().max(now);
        let joints = self.joints_at(t_end);
        if let Some(span) = self.following.spans.last_mut() {
            span.t_end = Some(t_end);
        }
        // The next move starts from where the object took the robot.
        self.planner.restart_from(joints, t_end);
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
