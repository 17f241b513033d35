//! The task's robot (§2.2–2.3): its model and kinematics, the path planner its moves
//! go to, and where it is at any controller time.
//!
//! A move instruction hands its move to the planner and tells the program when it
//! may go on: after a stop point when the robot stands still there; after a fly-by
//! point shortly before the robot would have to start braking for it (§2.3: the next
//! move must be planned in time, about 0.1 s ahead); at once with `\Conc`. A fly-by
//! move whose successor comes too late stops at its point: a corner path failure.

use std::collections::VecDeque;

use rapid_motion::frames::FrameChain;
use rapid_motion::kinematics::Opw;
use rapid_motion::plan::{AccelLimits, MoveRequest, PlannedMove, Planner};
use rapid_motion::robots::{default_model, RobotModel};
use rapid_motion::{Joints, MotionError};

/// How long before the robot would brake for a fly-by point the program goes on to
/// plan the next move (§2.3: "about 0.1 s" to plan the next move).
// uncertain: the servo lag (0–1 s, §2.3) that also lets logic run earlier is not
// modelled.
pub const PREFETCH: f64 = 0.1;

/// An output a move sets as the robot passes its point (MoveJDO, MoveLAO, …): in the
/// middle of the corner path, or at the stop point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathEvent {
    pub signal: u32,
    pub value: f64,
}

/// The robot of a motion task.
pub struct RobotState {
    pub model: &'static RobotModel,
    pub kin: Opw,
    planner: Planner,
    /// Final moves the robot may still be on, oldest first.
    ahead: VecDeque<PlannedMove>,
    /// Every final move, kept when a trace is asked for.
    pub recorded: Option<Vec<PlannedMove>>,
    /// The tool and work object frames of the last move (the active ones, for CRobT
    /// without arguments).
    pub active: FrameChain,
    /// When the robot stands still after its last final move.
    pub motion_end: f64,
    /// Moves planned so far.
    pub moves: u64,
    /// Fly-by points the robot had to stop at.
    pub corner_path_failures: u64,
    /// The SearchL under way.
    pub search: Option<super::search::Search>,
    /// The path event of each move given and not yet final, oldest first.
    events: VecDeque<Option<PathEvent>>,
    /// Path events whose time is known: (controller time, event).
    pub due: Vec<(f64, PathEvent)>,
}

impl Default for RobotState {
    /// The default robot (IRB 120-3/0.58) at its calibration position, all axes 0.
    // uncertain: a real robot starts wherever it stands; programs move to a home
    // position first, so the calibration position is our start.
    fn default() -> RobotState {
        RobotState::new(default_model())
    }
}

impl RobotState {
    pub fn new(model: &'static RobotModel) -> RobotState {
        let kin = model.kinematics();
        let planner = Planner::new([0.0; 6], AccelLimits::nominal(&model.max_speeds));
        RobotState {
            model,
            kin,
            planner,
            ahead: VecDeque::new(),
            recorded: None,
            active: FrameChain::default(),
            motion_end: 0.0,
            moves: 0,
            corner_path_failures: 0,
            search: None,
            events: VecDeque::new(),
            due: Vec::new(),
        }
    }

    /// Keeps every final move, for a trace.
    pub fn record(&mut self) {
        self.recorded.get_or_insert_with(Vec::new);
    }

    /// The settings moves are planned with from now on.
    pub fn set_settings(&mut self, settings: rapid_motion::plan::MotionSettings) {
        self.planner.set_settings(settings);
    }

    /// Where the last move given ends (the start of the next).
    pub fn end_joints(&self) -> Joints {
        self.planner.end_joints()
    }

    /// Gives the robot its next move at controller time `now`; returns when the
    /// program may go on. On an error nothing changes.
    pub fn push(
        &mut self,
        now: f64,
        request: &MoveRequest,
        conc: bool,
        event: Option<PathEvent>,
    ) -> Result<f64, MotionError> {
        if self.planner.pending_stop_time().is_some_and(|stop| now > stop) {
            // The program came too late: the waiting fly-by point became a stop point.
            self.flush();
        }
        self.planner.idle_until(now);
        let done = self.planner.push(&self.kin, request)?;
        self.events.push_back(event);
        if let Some(done) = done {
            self.finish(done);
        }
        self.moves += 1;
        if conc {
            return Ok(now);
        }
        if request.zone.is_stop() {
            return Ok(self.flush().max(now));
        }
        // The program goes on before the robot reaches the zone (§2.3): the zone's
        // length at the programmed speed ahead of where it would brake.
        let stop = self.planner.pending_stop_time().unwrap_or(now);
        let zone_time = if request.speed.v_tcp > 0.0 { request.zone.pzone_tcp / request.speed.v_tcp } else { 0.0 };
        Ok((stop - PREFETCH - zone_time).max(now))
    }

    /// Ends the queue: a waiting move stops at its point. Returns when the robot
    /// stands still.
    pub fn flush(&mut self) -> f64 {
        if let Some(last) = self.planner.flush() {
            self.finish(last);
        }
        self.motion_end
    }

    fn finish(&mut self, planned: PlannedMove) {
        if planned.corner_path_failure {
            self.corner_path_failures += 1;
        }
        if let Some(event) = self.events.pop_front().flatten() {
            // The middle of the corner path; at a stop point, when the robot stands there.
            self.due.push((planned.zone_entry + planned.corner_time / 2.0, event));
        }
        self.motion_end = self.motion_end.max(planned.end);
        if let Some(recorded) = &mut self.recorded {
            recorded.push(planned.clone());
        }
        self.ahead.push_back(planned);
    }

    /// The axis values at controller time `t`. On a move still waiting for its
    /// successor the robot is taken to be at that move's end.
    // uncertain: the position along a fly-by move that is not final yet is not known
    // until its corner is planned; its end point stands for it (a stop point before a
    // read-back, as the manual recommends, makes it exact).
    pub fn joints_at(&mut self, t: f64) -> Joints {
        while self.ahead.len() > 1 && self.ahead.front().is_some_and(|m| m.end < t) {
            self.ahead.pop_front();
        }
        if self.planner.has_pending() && t > self.planner.time() {
            return self.planner.end_joints();
        }
        match self.ahead.iter().find(|m| t <= m.end) {
            Some(m) if t >= m.start => m.sample(&self.kin, t).joints,
            Some(m) => m.sample(&self.kin, m.start).joints,
            None => self.ahead.back().map_or_else(|| self.planner.end_joints(), |m| m.end_joints),
        }
    }

    /// The robot stops where it is at time `t` (a search hit with a stop): the move it
    /// is on ends there and nothing planned after it is kept. Returns the joints.
    pub fn stop_at(&mut self, t: f64) -> Joints {
        while self.ahead.back().is_some_and(|m| m.start > t && self.ahead.len() > 1) {
            self.ahead.pop_back();
        }
        if let Some(last) = self.ahead.back_mut() {
            last.cut_at(&self.kin, t);
        }
        if let Some(recorded) = &mut self.recorded {
            while recorded.last().is_some_and(|m| m.start > t && recorded.len() > 1) {
                recorded.pop();
            }
            if let Some(last) = recorded.last_mut() {
                last.cut_at(&self.kin, t);
            }
        }
        let joints = self.ahead.back().map_or_else(|| self.planner.end_joints(), |m| m.end_joints);
        self.motion_end = self.ahead.back().map_or(t, |m| m.end);
        self.planner.restart_from(joints, self.motion_end);
        joints
    }
}
