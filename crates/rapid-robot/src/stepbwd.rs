//! StepBwdPath (manual §1.8, "通过RESTART事件程序沿路径后退"): from a RESTART event
//! routine, the robot stopped on its path moves StepLength mm back along it; when
//! the program starts again it first goes forward to where it stopped, then on along
//! the rest of its path.
//!
//! As we remember ABB's instruction manual (no public copy found): the step's speed
//! is the lowest of StepLength / StepTime, the programmed speed of the segment and
//! 250 mm/s; the first step may go back only within the segment the robot stopped
//! on; a step beyond the limit raises ERR_BWDLIMIT; the instruction belongs in a
//! RESTART event routine.

use crate::RobotResources;
use rapid_motion::plan::{AccelLimits, Mount, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData};
use rapid_motion::{Joints, Kinematics};

use super::pause::Pause;
use super::robot::RobotState;
use rapid_vm::ext::{Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// EventType's value while a RESTART event routine runs (EVENT_RESTART).
const EVENT_RESTART: u8 = 5;

/// The fastest a step back goes, mm/s.
const MAX_STEP_SPEED: f64 = 250.0;

/// The step at which the path walked back is measured, s.
const WALK_STEP: f64 = 0.001;

/// The steps back taken while the program stands: the moves and how far back the
/// robot is now along the segment it stopped on, with that segment's speed.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct StepBack {
    moves: Vec<PlannedMove>,
    back_mm: f64,
    segment_speed: f64,
}

impl StepBack {
    /// Where the steps have taken the robot at time `t`; None before the first.
    pub(super) fn joints_at<K: Kinematics + ?Sized>(&self, kin: &K, t: f64) -> Option<Joints> {
        let step = self.moves.iter().rev().find(|m| m.start <= t)?;
        Some(step.sample(kin, t).joints)
    }
}

/// `StepBwdPath StepLength, StepTime`: the robot moves StepLength mm back along its
/// stopped path; the instruction waits until it stands there.
// uncertain: outside a RESTART event routine execution stops (the controller's own
// error is not known); StepLength or StepTime not above 0 raise ERR_ARGVALERR; every
// step stays within the segment the robot stopped on (the manual lets later steps
// reach the segment before); the step is a straight line to the point StepLength
// back along the path (the path itself on linear segments), a stop point of the
// timing model.
pub(crate) fn step_bwd_path(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if ctx.resources.tasks.event != EVENT_RESTART {
        return Err(RapidError::fatal("StepBwdPath can only be used in a RESTART event routine"));
    }
    let (length, time) = (ctx.num(&args[0])?, ctx.num(&args[1])?);
    if !(length > 0.0 && length.is_finite() && time > 0.0 && time.is_finite()) {
        return Err(ctx.error(Err::ArgValue, "StepBwdPath needs StepLength and StepTime above 0"));
    }
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    let Some(pause) = robot.pause.as_ref() else {
        return Err(ctx.error(Err::BwdLimit, "the robot has no stopped path to step back on"));
    };
    if pause.regain.is_some() || robot.stored.is_some() {
        return Err(RapidError::fatal("StepBwdPath after StorePath or RestoPath is not supported by `rapid run` yet"));
    }
    let since = pause.since;
    let Some(segment) = robot.ahead.iter().rev().find(|m| m.start < since).cloned() else {
        return Err(ctx.error(Err::BwdLimit, "the robot has no stopped path to step back on"));
    };
    let moves_eax = segment.eax_at(segment.start).zip(segment.eax_end()).is_some_and(|(a, b)| a != b);
    if moves_eax {
        return Err(RapidError::fatal(
            "StepBwdPath on a segment that moves external axes is not supported by `rapid run` yet",
        ));
    }
    let tool = match segment.tool() {
        Mount::Held(tool) => tool,
        Mount::Stationary { .. } => {
            return Err(RapidError::fatal("StepBwdPath with a stationary tool is not supported by `rapid run` yet"))
        }
    };
    let (done_back, segment_speed, here) = match &pause.step {
        Some(step) => (step.back_mm, step.segment_speed, step.moves.last().map(|m| m.end_joints)),
        None => (0.0, peak_speed(robot, &segment, since), None),
    };
    let here = here.unwrap_or_else(|| segment.sample(&robot.kin, since).joints);
    let back_mm = done_back + length;
    let Some(at) = time_back_along(robot, &segment, since, back_mm) else {
        return Err(ctx.error(
            Err::BwdLimit,
            format!("StepBwdPath: {back_mm:.1} mm back is beyond the start of the segment the robot stopped on"),
        ));
    };
    let target = robot.kin.forward(&segment.sample(&robot.kin, at).joints) * tool;
    let speed = (length / time).min(segment_speed).min(MAX_STEP_SPEED);
    let step = linear_move(ctx, here, target, tool, speed, now)?;
    let wait = step.end - now;
    if let Some(pause) = ctx.resources.robot_mut().pause.as_mut() {
        let steps = pause.step.get_or_insert_with(|| StepBack { moves: Vec::new(), back_mm: 0.0, segment_speed });
        steps.back_mm = back_mm;
        steps.moves.push(step);
    }
    if wait > 0.0 {
        ctx.wait = Some(wait);
    }
    Ok(None)
}

/// At the start after steps back: the move forward from where the steps left the
/// robot to where it stopped, at the segment's speed, starting now.
// uncertain: the way back to the stop is a straight line at the segment's programmed
// speed ending in a stop point; from there the path goes on as after any stop.
pub(super) fn forward(ctx: &mut Ctx<'_>, pause: &Pause, step: &StepBack) -> Result<PlannedMove, RapidError> {
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    let here = step.moves.last().map_or_else(|| robot.planner.end_joints(), |m| m.end_joints);
    let Some(segment) = robot.ahead.iter().rev().find(|m| m.start < pause.since) else {
        return Err(RapidError::fatal("StepBwdPath: the stopped path is gone"));
    };
    let tool = match segment.tool() {
        Mount::Held(tool) => tool,
        Mount::Stationary { .. } => return Err(RapidError::fatal("StepBwdPath: a stationary tool")),
    };
    let target = robot.kin.forward(&segment.sample(&robot.kin, pause.since).joints) * tool;
    linear_move(ctx, here, target, tool, step.segment_speed, now)
}

/// Puts the steps back and the move forward into the robot's queue (and the trace)
/// in place of its standing still from `since` to where the forward move ends.
pub(super) fn splice(robot: &mut RobotState, since: f64, step: StepBack, forward: PlannedMove) {
    let until = forward.end;
    let mut detour = Vec::with_capacity(step.moves.len() * 2 + 2);
    let mut at = (since, robot.joints_at(since));
    for planned in step.moves.into_iter().chain(std::iter::once(forward)) {
        if planned.start > at.0 {
            detour.push(PlannedMove::standing(at.1, planned.tool(), at.0, planned.start));
        }
        at = (planned.end, planned.end_joints);
        detour.push(planned);
    }
    let replace = |moves: &mut Vec<PlannedMove>| {
        moves.retain(|m| !(m.start >= since - 1e-9 && m.end <= until + 1e-9 && m.start < until));
        let i = moves.iter().position(|m| m.start >= until - 1e-9).unwrap_or(moves.len());
        moves.splice(i..i, detour.iter().cloned());
    };
    let mut ahead: Vec<PlannedMove> = robot.ahead.drain(..).collect();
    replace(&mut ahead);
    robot.ahead = ahead.into();
    if let Some(recorded) = robot.recorded.as_mut() {
        replace(recorded);
    }
}

/// The segment's programmed speed, as the fastest the TCP went on it before `since`.
// uncertain: the speeddata is not kept with a planned move; its top speed stands for
// it (the same where the programmed speed was reached).
fn peak_speed(robot: &RobotState, segment: &PlannedMove, since: f64) -> f64 {
    let end = segment.end.min(since.max(segment.start));
    let n = ((end - segment.start) / WALK_STEP).ceil().clamp(1.0, 1e7) as usize;
    (0..=n)
        .map(|i| segment.sample(&robot.kin, segment.start + (end - segment.start) * i as f64 / n as f64).tcp_speed)
        .fold(0.0, f64::max)
}

/// The time on `segment` the TCP was `back_mm` along its path before `since`; None
/// when the segment's start is nearer.
fn time_back_along(robot: &RobotState, segment: &PlannedMove, since: f64, back_mm: f64) -> Option<f64> {
    let end = segment.end.min(since);
    let n = ((end - segment.start) / WALK_STEP).ceil().clamp(1.0, 1e7) as usize;
    let at = |i: usize| segment.start + (end - segment.start) * i as f64 / n as f64;
    let tcp = |t: f64| segment.sample(&robot.kin, t).tcp.translation.vector;
    let (mut walked, mut later) = (0.0, tcp(end));
    for i in (0..n).rev() {
        let here = tcp(at(i));
        let step = (later - here).norm();
        if walked + step >= back_mm - 1e-9 {
            let part = if step > 0.0 { (back_mm - walked) / step } else { 0.0 };
            return Some(at(i + 1) - part * (at(i + 1) - at(i)));
        }
        walked += step;
        later = here;
    }
    None
}

/// A linear move from `here` to the TCP pose `target` at `speed` mm/s, ending in a
/// stop point, starting at `now`.
fn linear_move(
    ctx: &mut Ctx<'_>,
    here: Joints,
    target: rapid_motion::Pose,
    tool: rapid_motion::Pose,
    speed: f64,
    now: f64,
) -> Result<PlannedMove, RapidError> {
    let settings = super::moves::planner_settings(ctx);
    let robot = ctx.resources.robot_mut();
    let mut planner = Planner::new(here, AccelLimits::nominal(&robot.model.max_speeds));
    planner.set_settings(settings);
    planner.idle_until(now);
    let speed = SpeedData { v_tcp: speed, ..SpeedData::VMAX };
    // A stop point: its work object plays no part.
    let wobj = rapid_motion::Pose::identity();
    let request =
        MoveRequest { target: Target::Linear(target), speed, zone: ZoneData::FINE, tool, held_object: None, wobj };
    let planned = planner.push(&robot.kin, &request).map_err(super::moves::motion_error)?;
    let mut planned =
        planned.or_else(|| planner.flush()).ok_or_else(|| RapidError::fatal("StepBwdPath: no move was planned"))?;
    // The arm alone steps: the external axes stand where the path stopped.
    let since = robot.pause.as_ref().map_or(now, |p| p.since);
    planned.hold_eax(robot.eax_at(since));
    Ok(planned)
}
