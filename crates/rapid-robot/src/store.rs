//! StorePath and RestoPath (§1.8, §2.2.6): path levels. StorePath sets the robot's
//! stopped path (the base path, level 1) aside with everything planned on it; the
//! program then moves the robot on path level 2, planned from where it stands.
//! RestoPath brings the base path back, still stopped: it goes on after the level 2
//! moves are done, when StartMove (or StartMoveRetry) comes; StartMove first takes
//! the robot back to where the base path stopped (pause.rs, regain).
//!
//! StorePath without StopMove (a trap during a move) stops the base path at the end
//! of the move the robot is on (the manual: "at the end of the instruction"), so the
//! robot finishes it before it takes level 2's moves.

use crate::RobotResources;
use std::collections::VecDeque;

use rapid_motion::plan::{Mount, PlannedMove, Planner};
use rapid_motion::Joints;

use super::pause::{pause_at, Pause};
use super::robot::{Action, Queued, RobotState};
use rapid_tasks::TaskingAccess;
use rapid_vm::ext::{Ctx, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// The base path while level 2 runs.
#[derive(Clone)]
pub struct Stored {
    /// Where and when the base path stopped.
    since: f64,
    stop_joints: Joints,
    pause: Pause,
    /// The planner with the base path's move still waiting for its successor.
    planner: Planner,
    events: VecDeque<Queued>,
    /// The base path's moves not done at `since`, whole (their times unshifted), and
    /// their copies in the trace.
    rest: Vec<PlannedMove>,
    recorded_rest: Vec<PlannedMove>,
    due: Vec<(f64, Action)>,
    motion_end: f64,
    hold_until: Option<f64>,
    /// Where the external axes stopped with the base path.
    eax: Option<rapid_motion::external::Eax>,
    /// The trace's facts of the base path's moves from `since` on.
    facts: super::robot::FactsAside,
}

/// `StorePath [\KeepSync]`: the base path is set aside; path level 2 begins. In
/// synchronized movement (MultiMove) the task moves on its own on level 2, as after
/// SyncMoveSuspend, unless `\KeepSync` keeps it synchronized; RestoPath brings the
/// synchronized movement back.
// uncertain: a second StorePath (one path is stored at a time) stops the program.
// uncertain: StorePath without \KeepSync is taken as StorePath \KeepSync followed
// by SyncMoveSuspend (the manual's example suspends after StorePath \KeepSync), so a
// SyncMoveResume on that level synchronizes the task again.
pub(crate) fn store_path(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if ctx.resources.robot_mut().stored.is_some() {
        return Err(RapidError::fatal("StorePath: a path is stored already (one at a time: RestoPath first)"));
    }
    let keep_sync = rapid_vm::ext::present(args.first());
    let now = ctx.time;
    if ctx.resources.robot_mut().pause.is_none() {
        let since = end_of_current_move(ctx.resources.robot_mut(), now);
        let pause = pause_at(ctx, since)?;
        ctx.resources.robot_mut().pause = Some(pause.unflagged());
    }
    let robot = ctx.resources.robot_mut();
    let Some(pause) = robot.pause.take() else { return Ok(None) };
    let since = pause.since;
    let here = robot.joints_at(since);
    let eax_here = robot.eax_at(since);
    // Stored again after a RestoPath, the path still goes on where it first stopped.
    let stop_joints = pause.regain.unwrap_or(here);
    let ahead = robot.ahead.drain(..).collect();
    let (keep, rest) = split_at(robot, ahead, since);
    robot.ahead = keep.into();
    let recorded_rest = match robot.recorded.take() {
        Some(recorded) => {
            let (keep, rest) = split_at(robot, recorded, since);
            robot.recorded = Some(keep);
            rest
        }
        None => Vec::new(),
    };
    let (due, later): (Vec<_>, Vec<_>) = robot.due.drain(..).partition(|&(t, _)| t <= since);
    robot.due = due;
    let mut planner = robot.planner.clone();
    planner.restart_from(here, since.max(now));
    // Level 2 starts where the external axes stopped, not where the base path ends.
    planner.set_eax(eax_here);
    let stored = Stored {
        since,
        stop_joints,
        pause,
        planner: std::mem::replace(&mut robot.planner, planner),
        events: std::mem::take(&mut robot.events),
        rest,
        recorded_rest,
        due: later,
        motion_end: std::mem::replace(&mut robot.motion_end, since),
        hold_until: robot.hold_until.take(),
        eax: eax_here,
        facts: robot.set_facts_aside(since),
    };
    robot.stored = Some(Box::new(stored));
    if let Some(mode) = ctx.resources.tasking_mut().sync_move.as_mut() {
        mode.suspended = !keep_sync;
    }
    if since > now {
        // uncertain: StorePath waits until the robot stands at the end of its move,
        // so CRobT after it (as the manual's examples do) reads the stop position.
        ctx.wait = Some(since - now);
    }
    Ok(None)
}

/// When the move the robot is on at `now` ends (a move still waiting for its
/// successor is made to stop at its point); `now` when it stands.
fn end_of_current_move(robot: &mut RobotState, now: f64) -> f64 {
    if let Some(m) = robot.ahead.iter().find(|m| m.end >= now) {
        return m.end;
    }
    if robot.planner.has_pending() {
        return robot.flush().max(now);
    }
    now
}

/// Splits moves at `since`: those done (a move under way cut there) and the rest,
/// whole.
fn split_at(robot: &RobotState, moves: Vec<PlannedMove>, since: f64) -> (Vec<PlannedMove>, Vec<PlannedMove>) {
    let (mut keep, mut rest) = (Vec::new(), Vec::new());
    for m in moves {
        if m.end <= since {
            keep.push(m);
        } else {
            if m.start < since {
                let mut done = m.clone();
                done.cut_at(&robot.kin, since);
                keep.push(done);
            }
            rest.push(m);
        }
    }
    (keep, rest)
}

/// The base path goes on with the external axes where it stopped them: if level 2
/// left them elsewhere, bringing them back is not modelled (StartMove's regain moves
/// the arm only), and RestoPath stops execution instead of letting them jump.
fn same_external_axes(robot: &super::robot::RobotState, stored: &Stored, level2_end: f64) -> Result<(), RapidError> {
    let (Some(now), Some(then)) = (robot.eax_at(level2_end), stored.eax) else { return Ok(()) };
    if now.iter().zip(then).all(|(a, b)| (a - b).abs() < 1e-6) {
        return Ok(());
    }
    Err(RapidError::fatal(
        "RestoPath: the external axes moved on path level 2; taking them back to the stored path is not supported yet",
    ))
}

/// `RestoPath`: the base path comes back, stopped where it was, after the moves of
/// level 2 are done (the instruction waits for them). StartMove lets it go on. A task
/// in synchronized movement moves synchronized again.
// uncertain: RestoPath without StorePath stops the program (the manual names no
// recoverable error for it).
pub(crate) fn resto_path(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let Some(stored) = ctx.resources.robot_mut().stored.take() else {
        return Err(RapidError::fatal("RestoPath: no path is stored (StorePath first)"));
    };
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    let level2_end = robot.flush().max(now);
    if let Err(err) = same_external_axes(robot, &stored, level2_end) {
        robot.stored = Some(stored);
        return Err(err);
    }
    super::moves::apply_due_events(ctx)?;
    let robot = ctx.resources.robot_mut();
    let Stored {
        since,
        stop_joints,
        mut pause,
        mut planner,
        events,
        rest,
        recorded_rest,
        due,
        motion_end,
        hold_until,
        facts,
        ..
    } = *stored;
    let shift = (level2_end - since).max(0.0);
    pause.delay(shift);
    pause.since = level2_end;
    pause.regain = Some(stop_joints);
    // Where level 2 left the robot, as the base path's pause begins (the robot stands
    // there until StartMove, whenever level 2's last move ended).
    let here = robot.planner.end_joints();
    let (tool, held_object) = super::moves::mount_of(&robot.active);
    let mount = held_object.map_or(Mount::Held(tool), |object| Mount::Stationary { tcp: tool, object });
    let mut stand = PlannedMove::standing(here, mount, level2_end, level2_end);
    stand.hold_eax(robot.eax_at(level2_end));
    robot.ahead.push_back(stand);
    let later = |moves: Vec<PlannedMove>| {
        moves.into_iter().map(move |mut m| {
            m.shift(shift);
            // The move under way goes on from where it stopped.
            m.start = m.start.max(level2_end).min(m.end);
            m
        })
    };
    robot.ahead.extend(later(rest));
    if let Some(recorded) = &mut robot.recorded {
        recorded.extend(later(recorded_rest));
    }
    robot.restore_facts(facts, since, shift);
    planner.delay_from(since, shift);
    robot.planner = planner;
    robot.events = events;
    robot.due.extend(due.into_iter().map(|(t, a)| (t + shift, a)));
    robot.motion_end = if motion_end > since { motion_end + shift } else { level2_end };
    robot.hold_until = hold_until;
    robot.pause = Some(pause);
    robot.path_rec.forget_back();
    // The base path was synchronized: so is the task again.
    // uncertain: also when the level 2 moves ended suspended (no SyncMoveResume).
    if let Some(mode) = ctx.resources.tasking_mut().sync_move.as_mut() {
        mode.suspended = false;
    }
    if level2_end > now {
        ctx.wait = Some(level2_end - now);
    }
    Ok(None)
}

/// Drops the queued moves that start at or after `t` (keeping at least one).
pub(super) fn drop_from(robot: &mut RobotState, t: f64) {
    while robot.ahead.len() > 1 && robot.ahead.back().is_some_and(|m| m.start >= t) {
        robot.ahead.pop_back();
    }
    if let Some(recorded) = &mut robot.recorded {
        while recorded.len() > 1 && recorded.last().is_some_and(|m| m.start >= t) {
            recorded.pop();
        }
    }
}

impl RobotState {
    /// Until when the program owes the robot the rest of a move's wait: its own, or,
    /// while path level 2 runs, the stored base path's (a trap that stored the path of
    /// the move the routine waits for and returned without RestoPath and StartMove: the
    /// routine waits on, §2.3, until the base path is restored, restarted and done).
    pub fn program_hold(&self) -> Option<f64> {
        self.hold_until.or_else(|| self.stored.as_ref().and_then(|s| s.hold_until))
    }
}

impl Stored {
    /// Whether the base path was stopped by StopMove (the stop-move state).
    pub(super) fn stop_move_act(&self) -> bool {
        self.pause.flagged()
    }

    /// How many of the base path's moves the robot had not started when it stopped:
    /// the path recorder's moves after the stop.
    pub(super) fn unstarted(&self) -> usize {
        let queued = self.rest.iter().filter(|m| m.start >= self.since && m.duration() > 0.0).count();
        queued + usize::from(self.planner.has_pending() && self.planner.time() >= self.since)
    }
}
