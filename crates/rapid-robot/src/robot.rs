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
use rapid_motion::{Joints, Kinematics, MotionError};
use rapid_syntax::Span;

/// How long before the robot would brake for a fly-by point the program goes on to
/// plan the next move (§2.3: "about 0.1 s" to plan the next move).
// uncertain: the servo lag (0–1 s, §2.3) that also lets logic run earlier is not
// modelled.
pub const PREFETCH: f64 = 0.1;

/// Where on a move's path an event happens.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum At {
    /// Where the robot passes the programmed point: the middle of the corner path, or
    /// the stop point (Move*DO, Trigg* distance 0).
    Point,
    /// This many mm of path before the point (TriggIO Distance).
    BeforePoint(f64),
    /// This many mm of path after the move's start (`\Start`).
    AfterStart(f64),
    /// This many seconds before the point (`\Time`).
    SecondsBefore(f64),
}

/// What an event does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Action {
    /// Sets an output to a value.
    Set { signal: u32, value: f64 },
    /// A world zone's output (WZDOSet): the zone supervision sets it whatever its access
    /// level, as the controller sets its system outputs (a read-only output is read-only
    /// for programs).
    ZoneSet { signal: u32, value: f64 },
    /// Fires an interrupt (TriggInt).
    Interrupt(u32),
    /// A trigger laid out or decided by the trigger family (TriggCheckIO, TriggRampAO,
    /// TriggSpeed, `\Inhib`): its key in `RobotState::trigg`.
    Special(u32),
}

/// An event a move fires as the robot passes a place on its path: Move*DO/AO/GO's
/// output, a trigger of TriggL/J/C. `shift` moves it in time (TriggIO's DODelay
/// later, TriggEquip's equipment lag earlier).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathEvent {
    pub at: At,
    pub shift: f64,
    pub action: Action,
}

/// How long the robot's past path is kept, s: questions about where it was (a search
/// hit found when the task next looks, a stop) reach back at most this far.
const KEEP_PAST: f64 = 1.0;

/// What a recorded move was, for `--trace` and `--report`: which instruction gave it
/// and where, its programmed point, zone and frames; once final, its times.
#[derive(Debug, Clone, PartialEq)]
pub struct MoveFacts {
    /// The instruction's name as the catalogue spells it (`MoveL`, `TriggL`, …); empty
    /// when the call was late-bound.
    pub instruction: &'static str,
    /// The program file (an index of the VM's sources, as in the event log) and the
    /// instruction's statement in it.
    pub file: usize,
    pub span: rapid_syntax::Span,
    /// The programmed TCP in the world frame (for MoveAbsJ, where its axis values put it).
    pub point: rapid_motion::Pose,
    /// The programmed zone radius, mm (`pzone_tcp`, `\Z`), and whether it is a stop point.
    pub zone: f64,
    pub fine: bool,
    /// The move's tool, work object and base frames.
    pub frames: FrameChain,
    /// From the planned move once final: its times, the zone it used (mm) and whether
    /// its fly-by point became a stop point.
    pub start: f64,
    pub end: f64,
    /// When the robot passes the point: the middle of its corner path, or when it
    /// stands at a stop point.
    pub passed: f64,
    pub zone_used: f64,
    pub corner_path_failure: bool,
    /// What its corner path blended, when it flew by its point.
    pub corner: Option<rapid_motion::plan::CornerKind>,
}

impl MoveFacts {
    /// The facts of a move no instruction described: where it ends, nothing else.
    fn unknown(point: rapid_motion::Pose) -> MoveFacts {
        MoveFacts {
            instruction: "",
            file: usize::MAX,
            span: rapid_syntax::Span::default(),
            point,
            zone: 0.0,
            fine: true,
            frames: FrameChain::default(),
            start: 0.0,
            end: 0.0,
            passed: 0.0,
            zone_used: 0.0,
            corner_path_failure: false,
            corner: None,
        }
    }
}

/// The step path distances are measured at, s.
const DISTANCE_STEP: f64 = 0.001;

/// What waits with a move until it is final: its path events and where it was
/// programmed.
#[derive(Debug, Default, Clone)]
pub struct Queued {
    pub(super) events: Vec<PathEvent>,
    place: Option<(usize, Span)>,
    /// The move is in the work object of this unit of another task (`foreign.rs`).
    foreign: Option<usize>,
}

/// The robot of a motion task.
pub struct RobotState {
    pub model: &'static RobotModel,
    pub kin: Opw,
    /// The robot's base frame in the world (MOC.cfg's `ROBOT -base_frame_pos/orient`);
    /// a track moves it further (`track.rs` `track_base`).
    pub base_frame: rapid_motion::Pose,
    pub(super) planner: Planner,
    /// Final moves the robot may still be on, oldest first.
    pub(super) ahead: VecDeque<PlannedMove>,
    /// Every final move, kept when a trace is asked for.
    pub recorded: Option<Vec<PlannedMove>>,
    /// The facts of the next move given (set by the move instruction just before
    /// [`RobotState::push`], only while recording).
    pub next_facts: Option<MoveFacts>,
    /// The facts of each move given and not yet final (while recording), oldest first.
    pending_facts: VecDeque<Option<MoveFacts>>,
    /// The facts of the final moves (while recording), in time order: each covers
    /// `start..end` of the recorded moves (a StopMove pause inside it included).
    pub recorded_facts: Vec<MoveFacts>,
    /// The tool and work object frames of the last move (the active ones, for CRobT
    /// without arguments).
    pub active: FrameChain,
    /// When the robot stands still after its last final move.
    pub motion_end: f64,
    /// Moves planned so far.
    pub moves: u64,
    /// Consecutive moves given with `\Conc` (moves.rs `count_conc`).
    pub(super) conc_run: u32,
    /// Fly-by points the robot had to stop at.
    pub corner_path_failures: u64,
    /// Where the moves whose fly-by point became a stop point were programmed (file,
    /// statement), for the event log: taken by the VM after each built-in.
    pub corner_failures: Vec<Option<(usize, Span)>>,
    /// Where the next move given is programmed (set by the move instruction just
    /// before [`RobotState::push`]).
    pub next_place: Option<(usize, Span)>,
    /// The SearchL under way.
    pub search: Option<super::search::Search>,
    /// What waits with each move given and not yet final, oldest first.
    pub(super) events: VecDeque<Queued>,
    /// Path events whose time is known: (controller time, action).
    pub due: Vec<(f64, Action)>,
    /// The triggers TriggIO, TriggEquip and TriggInt defined (triggdata holds an index).
    pub triggers: Vec<PathEvent>,
    /// The program waits for the robot until then, with interrupts ordered (traps run
    /// meanwhile).
    pub hold_until: Option<f64>,
    /// StopMove holds the robot.
    pub pause: Option<super::pause::Pause>,
    /// The shapes WZ*Def defined (shapedata holds an index) and the active world zones
    /// with whether the robot was last inside each.
    pub shapes: Vec<super::zones::ShapeData>,
    pub zones: Vec<Option<super::zones::Zone>>,
    pub(super) zone_inside: Vec<bool>,
    /// The time up to which the world zones were supervised along the path.
    pub(super) zones_until: f64,
    /// When the robot would enter a WZLimSup zone (execution stops).
    pub zone_violation: Option<f64>,
    /// The axes in independent mode (IndAMove …).
    pub independent: super::indep::Independent,
    /// The base path StorePath set aside (path level 2 while it is there).
    pub stored: Option<Box<super::store::Stored>>,
    /// The path recorder (PathRecStart …): the moves of the base path it recorded.
    pub path_rec: super::recorder::Recorder,
    /// The trigger family's definitions, deferred actions and runs (ramps, TriggSpeed).
    pub trigg: super::trigg::TriggState,
    /// Path correction: the generators, the total correction's time line, the moves
    /// made with `\Corr`.
    pub corr: super::corr::CorrState,
    /// The task's external units (none unless the configuration gives some).
    pub external: super::extax::ExternalUnits,
    /// The task's conveyors and the moving work objects the robot followed.
    pub following: super::conveyor::Following,
    /// The external axes' part of the next move given (set by the move instruction
    /// just before [`RobotState::push`]).
    pub(super) next_external: Option<rapid_motion::external::ExternalMove>,
    /// A 7-axis arm's axis 7 at the target of the robtarget move about to be given
    /// (`arm7.rs`), taken by the move.
    pub(super) next_axis7: Option<f64>,
    /// The next move given is in the work object of this unit of another task (set by
    /// the move instruction just before [`RobotState::push`]).
    pub(super) next_foreign: Option<usize>,
    /// The active work object rides this unit of another task (its frame follows it).
    pub(super) active_foreign: Option<usize>,
    /// The robot's configured name when it is not `ROB_n` (MOC.cfg's `ROBOT -name`,
    /// `ROB_L` of a two-arm system): what RobName returns and mecunit data names it.
    pub name: Option<String>,
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
        let planner = Planner::new(model.calibration(), AccelLimits::nominal(&model.max_speeds));
        let mut state = RobotState {
            model,
            kin,
            base_frame: rapid_motion::Pose::identity(),
            planner,
            ahead: VecDeque::new(),
            recorded: None,
            next_facts: None,
            pending_facts: VecDeque::new(),
            recorded_facts: Vec::new(),
            active: FrameChain::default(),
            motion_end: 0.0,
            moves: 0,
            conc_run: 0,
            corner_path_failures: 0,
            corner_failures: Vec::new(),
            next_place: None,
            search: None,
            events: VecDeque::new(),
            due: Vec::new(),
            triggers: Vec::new(),
            hold_until: None,
            pause: None,
            shapes: Vec::new(),
            zones: Vec::new(),
            zone_inside: Vec::new(),
            zones_until: 0.0,
            zone_violation: None,
            independent: Default::default(),
            stored: None,
            path_rec: super::recorder::Recorder::default(),
            trigg: Default::default(),
            corr: Default::default(),
            external: Default::default(),
            following: Default::default(),
            next_external: None,
            next_axis7: None,
            next_foreign: None,
            active_foreign: None,
            name: None,
        };
        if state.kin.redundant() {
            // A 7-axis arm's axis 7 rides in eax_a from the start (`arm7.rs`).
            state.configure_external(Vec::new());
        }
        state
    }

    /// Puts the robot, before it has moved, at axis values `joints` (degrees) instead of
    /// the calibration position: the start pose a cell configures. Fails, naming the
    /// axis, when one is outside its range or not a number.
    pub fn start_at(&mut self, joints: Joints) -> Result<(), String> {
        let limits = self.kin.limits();
        for (axis, (q, (lo, hi))) in joints.iter().zip(limits).enumerate() {
            if !q.is_finite() || self.kin.limit_violation(&joints) == Some(axis + 1) {
                return Err(format!(
                    "the start position puts axis {} of the robot at {q}°, outside its range {lo}° … {hi}°",
                    axis + 1
                ));
            }
        }
        self.planner = Planner::new(joints, AccelLimits::nominal(&self.model.max_speeds));
        Ok(())
    }

    /// Keeps every final move, for a trace.
    pub fn record(&mut self) {
        self.recorded.get_or_insert_with(Vec::new);
    }

    /// The settings moves are planned with from now on.
    pub fn set_settings(&mut self, settings: rapid_motion::plan::MotionSettings) {
        self.planner.set_settings(settings);
    }

    /// Whether the robot moves at `t` (or has a move given that is not final yet).
    pub fn moving_at(&self, t: f64) -> bool {
        self.motion_end > t || self.planner.has_pending()
    }

    /// From when the robot stands still unless the program gives it another move: the
    /// end of its last final move, or where the move waiting for its successor would
    /// stop (its fly-by point then becomes a stop point); while StopMove holds its path,
    /// from where the path stopped.
    pub fn still_from(&self) -> f64 {
        if let Some(pause) = &self.pause {
            return pause.since;
        }
        self.motion_end.max(self.planner.pending_stop_time().unwrap_or(f64::NEG_INFINITY))
    }

    /// Where the flange is for axes `joints`, in the base frame, and their confdata, by
    /// this robot's own kinematics.
    pub fn flange_of(&self, joints: &Joints) -> (rapid_motion::Pose, rapid_motion::confdata::ConfData) {
        use rapid_motion::Kinematics;
        (self.kin.forward(joints), rapid_motion::confdata::confdata_of(&self.kin, joints))
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
        events: Vec<PathEvent>,
    ) -> Result<f64, MotionError> {
        if self.planner.pending_stop_time().is_some_and(|stop| now > stop) {
            // The program came too late: the waiting fly-by point became a stop point.
            self.flush();
        }
        self.planner.idle_until(now);
        self.forget_before(now - KEEP_PAST);
        let facts = self.next_facts.take();
        let corrected = std::mem::take(&mut self.corr.next);
        if !self.planner.has_pending() {
            self.corr.pending = false;
        }
        let (from, eax_from) = (self.planner.end_joints(), self.planner.end_eax());
        let external = self.next_external.take();
        let foreign = self.next_foreign.take();
        self.next_axis7 = None;
        let done = self.planner.push_with(&self.kin, request, external.as_ref())?;
        if let Some(eax) = self.planner.end_eax().filter(|_| self.kin.redundant()) {
            // A 7-axis arm stands with axis 7 where its last move leaves it.
            self.kin = self.kin.with_axis7(eax[0]);
        }
        if let Some(f) = foreign {
            self.busy_in(f);
        }
        if self.stored.is_none() {
            // Only the base path is recorded; level 2's moves (and the recorder's own) are not.
            let in_moving_object = foreign.is_some() || self.following.open().is_some();
            self.path_rec.note((from, eax_from), request, in_moving_object);
        }
        self.events.push_back(Queued { events, place: self.next_place.take(), foreign });
        if self.recorded.is_some() {
            self.pending_facts.push_back(facts);
        }
        if let Some(done) = done {
            self.finish(done);
        }
        self.publish_tail();
        self.corr.pending = corrected;
        self.place_early_events();
        self.supervise_provisional();
        self.moves += 1;
        if conc {
            // A stop point needs no successor to be planned: the robot is on its way.
            if request.zone.is_stop() {
                self.flush();
            }
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
            self.publish_tail();
        }
        self.motion_end
    }

    /// The events of the waiting (fly-by) move placed from its start that come before
    /// it could start braking: their time is already exact, so the I/O system gets
    /// them now rather than when the move becomes final, which may be long after
    /// (TriggL \Start on a slow weld seam).
    fn place_early_events(&mut self) {
        let Some((provisional, braking)) = self.planner.provisional() else { return };
        let Some(Queued { events, .. }) = self.events.back_mut() else { return };
        // The trigger family lays its own events (ramps, TriggSpeed, checks) out on the
        // final move: those wait for it.
        let early = |e: &PathEvent| matches!(e.at, At::AfterStart(_)) && !matches!(e.action, Action::Special(_));
        if !events.iter().any(early) {
            return;
        }
        let mut later = Vec::with_capacity(events.len());
        for event in std::mem::take(events) {
            let (At::AfterStart(d), false) = (event.at, matches!(event.action, Action::Special(_))) else {
                later.push(event);
                continue;
            };
            let at = self.time_at_distance(&provisional, provisional.zone_entry, d, true);
            if at <= braking {
                self.due.push(((at + event.shift).max(provisional.start), event.action));
            } else {
                later.push(event);
            }
        }
        if let Some(queued) = self.events.back_mut() {
            queued.events = later;
        }
    }

    pub(super) fn finish(&mut self, planned: PlannedMove) {
        self.following.begin_fade(&planned);
        self.following.end_fade(&planned);
        let Queued { events, place, foreign } = self.events.pop_front().unwrap_or_default();
        if let Some(f) = foreign {
            self.busy_until(f, planned.end);
        }
        self.publish_final(&planned);
        if planned.corner_path_failure {
            self.corner_path_failures += 1;
            self.corner_failures.push(place);
        }
        let mut specials = Vec::new();
        if !events.is_empty() {
            // The point: the middle of the corner path; at a stop point, when the robot
            // stands there.
            let point = planned.zone_entry + planned.corner_time / 2.0;
            for event in events {
                let at = match event.at {
                    At::Point => point,
                    At::SecondsBefore(s) => point - s,
                    At::BeforePoint(d) => self.time_at_distance(&planned, point, d, false),
                    At::AfterStart(d) => self.time_at_distance(&planned, point, d, true),
                };
                if let Action::Special(key) = event.action {
                    specials.push((at, event.shift, key));
                    continue;
                }
                self.due.push(((at + event.shift).max(planned.start), event.action));
            }
        }
        self.trigg.on_move(&self.kin, &planned, &specials, &mut self.due);
        self.corr.on_final(&self.kin, &planned);
        self.supervise_final(&planned);
        self.motion_end = self.motion_end.max(planned.end);
        if let Some(recorded) = &mut self.recorded {
            recorded.push(planned.clone());
            // A move given without its facts still gets a record, so that every
            // recorded move has one and the times line up.
            let mut facts = match self.pending_facts.pop_front().flatten() {
                Some(facts) => facts,
                None => MoveFacts::unknown(planned.tool().tcp(&self.kin.forward(&planned.end_joints))),
            };
            facts.start = planned.start;
            facts.end = planned.end;
            facts.passed = planned.zone_entry + planned.corner_time / 2.0;
            facts.zone_used = planned.zone;
            facts.corner_path_failure = planned.corner_path_failure;
            facts.corner = planned.corner_kind();
            self.recorded_facts.push(facts);
        }
        self.ahead.push_back(planned);
    }

    /// Drops the moves that ended before `t` (the last one stays: the robot stands at
    /// its end), so a long program does not keep its whole path.
    fn forget_before(&mut self, t: f64) {
        while self.ahead.len() > 1 && self.ahead.front().is_some_and(|m| m.end < t) {
            self.ahead.pop_front();
        }
        if self.recorded.is_none() {
            self.corr.forget_before(t);
        }
    }

    /// The axis values at controller time `t`. On a move still waiting for its
    /// successor the robot is taken to be at that move's end.
    // uncertain: on a fly-by move that is not final yet the corner is not planned; the
    // move's stop plan stands for it (exact until the robot would brake).
    pub fn joints_at(&mut self, t: f64) -> Joints {
        let planned = self.planned_joints_at(t);
        // A robot following a conveyor object is shifted by the object's travel.
        let mut joints = self.tracked_joints(t, planned);
        // Axes in independent mode are where their own motion has taken them.
        self.independent.apply(&mut joints, t);
        joints
    }

    /// An axis leaves independent mode at `position` (IndReset): the planner takes it
    /// on from there once the robot stands still.
    pub fn take_over_axis(&mut self, axis: usize, position: f64, now: f64) {
        let end = self.flush().max(now);
        let mut joints = self.planned_joints_at(end);
        joints[axis] = position;
        self.planner.restart_from(joints, end);
        // The robot stands at the last final move's end: from now on with the axis
        // where the reset left it (its independent motion until now stays in history).
        if let Some(last) = self.ahead.back_mut().filter(|m| m.end <= end) {
            last.end_joints[axis] = position;
        }
        if let Some(last) = self.recorded.as_mut().and_then(|r| r.last_mut()).filter(|m| m.end <= end) {
            last.end_joints[axis] = position;
        }
    }

    /// A sample of the trace with the independent axes put in, its TCP and flange
    /// following them.
    pub fn with_independent(
        &self,
        mut sample: rapid_motion::plan::Sample,
        mount: &rapid_motion::plan::Mount,
    ) -> rapid_motion::plan::Sample {
        if self.independent.apply(&mut sample.joints, sample.time) {
            sample.flange = self.kin.forward(&sample.joints);
            sample.tcp = mount.tcp(&sample.flange);
        }
        sample
    }

    /// The axis values the planned moves give at time `t`.
    fn planned_joints_at(&mut self, t: f64) -> Joints {
        // A stopped robot stepped back along its path (StepBwdPath) is where that took it.
        if let Some(joints) = self.pause.as_ref().and_then(|p| p.step.as_ref()).and_then(|s| s.joints_at(&self.kin, t))
        {
            return joints;
        }
        // A stopped robot stands where it stopped.
        let t = self.pause.as_ref().map_or(t, |p| t.min(p.since));
        self.forget_before(t);
        if self.planner.has_pending() && t > self.planner.time() {
            // On the move still waiting for its successor: until it could start braking
            // it moves as if it stopped at its point, so that plan gives where it is
            // (exact before the braking; within the corner the stop plan stands for it).
            return match self.planner.provisional() {
                Some((planned, _)) => planned.sample(&self.kin, t).joints,
                None => self.planner.end_joints(),
            };
        }
        match self.ahead.iter().find(|m| t <= m.end) {
            Some(m) if t >= m.start => self.corr.correct(&self.kin, m, m.sample(&self.kin, t)).joints,
            Some(m) => self.corr.correct(&self.kin, m, m.sample(&self.kin, m.start)).joints,
            // Standing after a corrected move: where its correction left the robot.
            None if self.corr.active() => self.ahead.back().map_or_else(
                || self.planner.end_joints(),
                |m| self.corr.correct(&self.kin, m, m.sample(&self.kin, m.end)).joints,
            ),
            None => self.ahead.back().map_or_else(|| self.planner.end_joints(), |m| m.end_joints),
        }
    }

    /// The robot brakes on its path from time `t` to standstill in `stop_time` (a
    /// search hit with a stop): the move it is on ends where it stands then, and
    /// nothing planned after it is kept. Returns when it stands still.
    pub fn brake_at(&mut self, t: f64, stop_time: f64) -> f64 {
        let Some(on) = self.ahead.iter().find(|m| m.start <= t && t < m.end).cloned() else {
            self.stop_at(t);
            return t;
        };
        let mut braked = on.clone();
        braked.brake_at(&self.kin, t, stop_time);
        if braked.end >= on.end {
            self.stop_at(on.end);
            return on.end;
        }
        let end = braked.end;
        self.stop_at(end);
        if let Some(last) = self.ahead.back_mut().filter(|m| m.start == on.start) {
            *last = braked.clone();
        }
        // The external axes stop where the braked move leaves them.
        if let Some(eax) = braked.eax_end() {
            self.planner.set_eax(Some(eax));
        }
        if let Some(last) = self.recorded.as_mut().and_then(|r| r.last_mut()).filter(|m| m.start == on.start) {
            *last = braked;
        }
        self.republish();
        end
    }

    /// The robot stops where it is at time `t` (a search hit with a stop): the move it
    /// is on ends there and nothing planned after it is kept. Returns the joints.
    pub fn stop_at(&mut self, t: f64) -> Joints {
        self.zones_stop_at(t);
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
            // The move that was waiting for its successor is gone with the planner's queue.
            self.pending_facts.clear();
            let facts = &mut self.recorded_facts;
            while facts.last().is_some_and(|f| f.start > t && facts.len() > 1) {
                facts.pop();
            }
            if let Some(last) = facts.last_mut() {
                last.end = last.end.min(t);
            }
        }
        // The path events of the move that waited for its successor go with it: the
        // next move to become final must not fire them.
        for f in self.events.drain(..).filter_map(|q| q.foreign).collect::<Vec<_>>() {
            self.busy_until(f, t);
        }
        self.corr.stop_at(t);
        let joints = self.ahead.back().map_or_else(|| self.planner.end_joints(), |m| m.end_joints);
        self.motion_end = self.ahead.back().map_or(t, |m| m.end);
        let eax = self.ahead.back().and_then(|m| m.eax_end()).or(self.planner.end_eax());
        self.planner.restart_from(joints, self.motion_end);
        self.planner.set_eax(eax);
        self.republish();
        joints
    }

    /// When the TCP is `d` mm of path after the move's start (`from_start`), or before
    /// its point (at time `point`), measured along the sampled path.
    fn time_at_distance(&self, planned: &PlannedMove, point: f64, d: f64, from_start: bool) -> f64 {
        let steps = (((point - planned.start) / DISTANCE_STEP).ceil() as usize).min(1_000_000);
        let mut marks = Vec::with_capacity(steps + 1);
        let mut last = planned.sample(&self.kin, planned.start).tcp.translation.vector;
        let mut travelled = 0.0;
        marks.push((planned.start, 0.0));
        for i in 1..=steps {
            let t = (planned.start + i as f64 * DISTANCE_STEP).min(point);
            let here = planned.sample(&self.kin, t).tcp.translation.vector;
            travelled += (here - last).norm();
            last = here;
            marks.push((t, travelled));
        }
        let target = if from_start { d } else { travelled - d }.clamp(0.0, travelled);
        marks.iter().find(|&&(_, s)| s >= target).map_or(point, |&(t, _)| t)
    }

    /// StartMove: the robot stood still from `since` for `dt` seconds, so what was
    /// planned after `since` comes that much later; the move it was on is split into
    /// the part done, the standstill and the rest.
    pub fn resume_after(&mut self, since: f64, dt: f64) {
        if self.zones_until > since {
            self.zones_until += dt;
        }
        let kin = &self.kin;
        let pause = |moves: Vec<PlannedMove>| -> Vec<PlannedMove> {
            let mut out = Vec::with_capacity(moves.len() + 2);
            for mut planned in moves {
                if planned.end <= since {
                    out.push(planned);
                } else if planned.start >= since {
                    planned.shift(dt);
                    out.push(planned);
                } else {
                    let mut done = planned.clone();
                    done.cut_at(kin, since);
                    let mut stand = PlannedMove::standing(done.end_joints, planned.tool(), since, since + dt);
                    stand.hold_eax(done.eax_end());
                    planned.shift(dt);
                    // The rest goes on from where the robot stopped: the part done before
                    // the stop is `done`'s, not to be walked (or traced) again.
                    planned.start = since + dt;
                    out.extend([done, stand, planned]);
                }
            }
            out
        };
        self.ahead = pause(self.ahead.drain(..).collect()).into();
        if let Some(recorded) = self.recorded.take() {
            self.recorded = Some(pause(recorded));
        }
        for facts in &mut self.recorded_facts {
            if facts.start >= since {
                facts.start += dt;
            }
            if facts.end > since {
                facts.end += dt;
            }
            if facts.passed > since {
                facts.passed += dt;
            }
        }
        self.planner.delay_from(since, dt);
        if self.motion_end > since {
            self.motion_end += dt;
        }
        for (t, _) in &mut self.due {
            if *t > since {
                *t += dt;
            }
        }
        self.trigg.delay_from(since, dt);
        self.corr.delay_from(since, dt);
        self.republish();
    }
}

/// The trace's facts of a stored base path (StorePath): those of its moves not yet
/// final (waiting in the stored planner), and those of its recorded moves from where it
/// stopped.
#[derive(Debug, Clone, Default)]
pub(super) struct FactsAside {
    pending: VecDeque<Option<MoveFacts>>,
    rest: Vec<MoveFacts>,
}

impl RobotState {
    /// StorePath at `since`: the base path's facts from there on are set aside with it,
    /// so the moves of path level 2 are traced with their own instructions.
    pub(super) fn set_facts_aside(&mut self, since: f64) -> FactsAside {
        let pending = std::mem::take(&mut self.pending_facts);
        let facts = &mut self.recorded_facts;
        let at = facts.iter().position(|f| f.start >= since).unwrap_or(facts.len());
        let mut rest = facts.split_off(at);
        if let Some(cut) = facts.last_mut().filter(|f| f.end > since) {
            // The move under way: done up to `since`, the rest after level 2.
            let mut rest_of_it = cut.clone();
            rest_of_it.start = since;
            cut.end = since;
            rest.insert(0, rest_of_it);
        }
        FactsAside { pending, rest }
    }

    /// RestoPath: the base path's facts come back after level 2's, `shift` later (as
    /// its moves, which waited that long from `since`).
    pub(super) fn restore_facts(&mut self, aside: FactsAside, since: f64, shift: f64) {
        self.pending_facts = aside.pending;
        for mut facts in aside.rest {
            facts.start += shift;
            facts.end += shift;
            if facts.passed > since {
                facts.passed += shift;
            }
            self.recorded_facts.push(facts);
        }
    }
}
