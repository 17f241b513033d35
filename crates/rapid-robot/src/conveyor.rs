//! Conveyor tracking (§1.8 传送带跟踪: WaitWObj, DropWObj): a conveyor is a simulated
//! axis whose speed is an analog input (mm/s) and whose sync switch is a digital input
//! (each rising edge puts an object at distance 0), both driven by the stimulus. An
//! object's distance is how far the conveyor has moved since its edge.
//!
//! WaitWObj connects a work object whose `ufmec` names the conveyor (`ufprog` FALSE)
//! to the first object in the start window. Moves in that work object are then
//! planned with the object frozen where it is when the first of them starts (the
//! conveyor's base frame moved along its x axis by the object's distance), and the
//! robot's path is shifted by how far the object has moved since: the robot follows
//! it. From a fly-by point in a fixed work object the object is frozen where it will
//! be when the robot would stand at that point, and the following fades in over the
//! corner ([`Fade`]). The first move in a fixed work object ends the tracking: given in
//! time after a conveyor fly-by point, over a corner (the last conveyor move rebased to
//! where the object will be, the following fading out); else the last conveyor point
//! becomes a stop point. DropWObj then releases the object.
//!
//! The same following carries the robot with a work object an external unit's axes
//! move (`Mover::Unit`: a turntable, a positioner, coordinated motion): [`Following`]
//! keeps the spans of time in which the robot followed either kind.
// uncertain: how the following fades in and out over its corners (`Fade`) is ours. The
// tracking robot's axis speeds are not re-checked.

use std::collections::VecDeque;

use nalgebra::{Translation3, Vector3};
use rapid_motion::external::{Eax, UnitChain};
use rapid_motion::plan::Sample;
use rapid_motion::{Joints, Kinematics, Pose};

/// A conveyor as the configuration describes it.
#[derive(Debug, Clone, PartialEq)]
pub struct ConveyorConfig {
    /// The conveyor's mechanical unit (a wobj's `ufmec`).
    pub name: String,
    /// The digital input of the sync switch and the analog input of the speed (mm/s).
    pub sync: u32,
    pub speed: u32,
    /// The conveyor's base frame in the world frame; objects move along its x axis.
    pub base: Pose,
    /// Objects farther than this from the sync switch (mm) are past the start window:
    /// WaitWObj skips them.
    pub start_window: f64,
    /// A tracked object farther than this (mm) is out of the robot's tracking range.
    pub max_dist: f64,
}

/// A conveyor and its objects.
#[derive(Debug, Clone, PartialEq)]
pub struct Conveyor {
    pub config: ConveyorConfig,
    /// (time, position, speed): the position grows linearly from each entry on.
    profile: Vec<(f64, f64, f64)>,
    /// How much of the I/O change log was read.
    seen: usize,
    /// The conveyor position at which each waiting object passed the sync switch.
    queue: VecDeque<f64>,
    /// The connected object's sync position.
    pub connected: Option<f64>,
}

impl Conveyor {
    /// A conveyor at position 0 moving at `speed` (the speed input's value at start).
    pub fn new(config: ConveyorConfig, speed: f64) -> Conveyor {
        Conveyor { config, profile: vec![(0.0, 0.0, speed)], seen: 0, queue: VecDeque::new(), connected: None }
    }

    /// Where the conveyor is at time `t`, mm (after the last known change, at the last
    /// known speed).
    pub fn position(&self, t: f64) -> f64 {
        let i = self.profile.partition_point(|&(t0, _, _)| t0 <= t).saturating_sub(1);
        let (t0, p0, v) = self.profile[i];
        p0 + v * (t - t0).max(0.0)
    }

    /// The connected object's distance from the sync switch at `t`.
    pub fn distance(&self, t: f64) -> Option<f64> {
        self.connected.map(|sync| self.position(t) - sync)
    }

    /// Reads the I/O changes not read yet: speed changes and objects at the switch.
    pub fn refresh(&mut self, io: &rapid_io::IoSystem) {
        let changes = io.changes();
        for change in changes.get(self.seen..).unwrap_or(&[]) {
            if change.id == self.config.speed {
                let p = self.position(change.time);
                self.profile.push((change.time, p, change.new));
            } else if change.id == self.config.sync && change.old == 0.0 && change.new != 0.0 {
                let p = self.position(change.time);
                self.queue.push_back(p);
            }
        }
        self.seen = changes.len();
    }

    /// Drops the objects past the start window at `t`; the first one left, if any.
    pub fn first_in_window(&mut self, t: f64) -> Option<f64> {
        let here = self.position(t);
        while self.queue.front().is_some_and(|&sync| here - sync > self.config.start_window) {
            self.queue.pop_front();
        }
        self.queue.front().copied()
    }

    /// Connects the first object of the queue (taken out of it).
    pub fn connect_first(&mut self) {
        self.connected = self.queue.pop_front();
    }

    /// When an object at sync position `sync` will be `dist` from the switch, at the
    /// speed known now; `None` when the conveyor stands.
    pub fn time_at_distance(&self, sync: f64, dist: f64, now: f64) -> Option<f64> {
        let (_, _, v) = *self.profile.last()?;
        let left = sync + dist - self.position(now);
        if left <= 0.0 {
            return Some(now);
        }
        (v > 0.0).then(|| now + left / v)
    }

    /// The object frame's user frame for an object `distance` from the switch.
    pub fn frame_at(&self, distance: f64) -> Pose {
        self.config.base * Translation3::new(distance, 0.0, 0.0)
    }
}

/// What carries a work object the robot follows.
// A unit's chain is a few hundred bytes; a mover is kept once per span of following,
// so it stays inline (and Copy) rather than boxed.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mover {
    /// A conveyor (its index) and the connected object's sync position.
    Conveyor { conveyor: usize, object: f64 },
    /// An external unit (its index) whose axes carry the work object along `chain`: a
    /// turntable turns it about its frame's z axis, a linear unit moves it along its
    /// frame's x axis, a positioner's tilt axis carries its turntable.
    Unit { unit: usize, chain: UnitChain },
    /// A unit of another motion task (its index among the task's foreign units,
    /// `foreign.rs`), carrying the work object along `chain` as its own task moves it.
    Foreign { unit: usize, chain: UnitChain },
}

/// Where a mover is: a conveyor object's distance from the sync switch (in the first
/// value), or the unit's external axes.
pub type MoverAt = Eax;

/// A stretch of time in which the robot follows a moving work object: the moves made in
/// it were planned with the mover at `at_ref`.
#[derive(Debug, Clone, PartialEq)]
pub struct Span {
    pub mover: Mover,
    pub t_ref: f64,
    pub at_ref: MoverAt,
    /// When the robot stopped following it (the end of its last move in it).
    pub t_end: Option<f64>,
    /// How the following begins: at once from a stop point, or faded in over the
    /// corner from a fly-by point in a fixed work object.
    pub fade: Fade,
    /// How it ends: at a stop point (`None`), or faded out over the corner into a move
    /// in a fixed work object (the last move rebased to where the object would be when
    /// it ends, `at_ref` that place; see `tracking.rs` `blend_exit`).
    pub exit: Fade,
    /// Where the mover was when the moves' frames were frozen (`at_ref` but for a rebased
    /// last move): the trace's work-object columns take the object's travel from there.
    pub frames_ref: MoverAt,
}

/// How a following begins (§2.2.3: a change from uncoordinated to coordinated motion
/// gets a corner path, joint-interpolated, rather than a stop).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fade {
    /// From a stop point: the frames were frozen where the robot stood.
    None,
    /// From a fly-by point whose corner is not planned yet.
    Pending,
    /// Over this time window (the corner into the first following move) the robot is
    /// carried by a growing part of the object's travel since the frames were frozen:
    /// none at its start, all of it at its end, both smoothly.
    Window(f64, f64),
}

/// After a fly-by point that became a stop point, the following fades in over this
/// long (s).
// uncertain: the controller's catching up with a moving object is not public.
const FADE_AFTER_STOP: f64 = 0.1;

impl Fade {
    /// The window over which a following that ends with move `planned` fades out: its
    /// corner path, or its last moments before it stands.
    pub fn before_end(planned: &rapid_motion::plan::PlannedMove) -> Fade {
        match planned.corner_time > 0.0 {
            true => Fade::Window(planned.zone_entry, planned.end),
            false => Fade::Window((planned.zone_entry - FADE_AFTER_STOP).max(planned.start), planned.zone_entry),
        }
    }

    /// The window over which a following that began at fly-by point `planned` fades
    /// in: its corner path, or a short time after it stopped.
    pub fn after(planned: &rapid_motion::plan::PlannedMove) -> Fade {
        match planned.corner_time > 0.0 {
            true => Fade::Window(planned.zone_entry, planned.end),
            false => Fade::Window(planned.end, planned.end + FADE_AFTER_STOP),
        }
    }

    /// How much of the object's travel carries the robot at `t`, 0 to 1.
    fn weight(&self, t: f64) -> f64 {
        let Fade::Window(a, b) = *self else { return 1.0 };
        // A window that is empty (or not a number) fades in at once.
        let empty = b.partial_cmp(&a) != Some(std::cmp::Ordering::Greater);
        if empty || t >= b {
            return 1.0;
        }
        let x = ((t - a) / (b - a)).clamp(0.0, 1.0);
        x * x * (3.0 - 2.0 * x)
    }

    fn covers(&self, t: f64) -> bool {
        matches!(*self, Fade::Window(a, b) if a <= t && t < b)
    }
}

impl Span {
    /// Whether the robot follows a conveyor object (not a unit's work object).
    pub fn is_conveyor(&self) -> bool {
        matches!(self.mover, Mover::Conveyor { .. })
    }
}

impl Mover {
    /// The motion (world frame) that carries an object from the mover at `from` to `to`.
    pub fn carry(&self, conveyors: &[Conveyor], from: &MoverAt, to: &MoverAt) -> Pose {
        match *self {
            Mover::Conveyor { conveyor, .. } => {
                let dir = conveyors[conveyor].config.base.rotation * Vector3::x();
                Pose::from_parts(Translation3::from(dir * (to[0] - from[0])), nalgebra::UnitQuaternion::identity())
            }
            Mover::Unit { chain, .. } | Mover::Foreign { chain, .. } => chain.carry(from, to),
        }
    }

    /// The user frame of the carried work object with the mover at `at`.
    pub fn user_frame(&self, conveyors: &[Conveyor], at: &MoverAt) -> Pose {
        match *self {
            Mover::Conveyor { conveyor, .. } => conveyors[conveyor].frame_at(at[0]),
            Mover::Unit { chain, .. } | Mover::Foreign { chain, .. } => chain.frame_at(at),
        }
    }
}

/// What the robot of a motion task follows: its conveyors, and the spans of time in
/// which it followed a moving work object (a conveyor's object or a unit's).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Following {
    pub conveyors: Vec<Conveyor>,
    pub spans: Vec<Span>,
    /// The first time the tracking robot could not reach its shifted path.
    pub unreachable: Option<f64>,
}

impl Following {
    /// The conveyor of this name.
    pub fn find(&self, name: &str) -> Option<usize> {
        self.conveyors.iter().position(|c| c.config.name.eq_ignore_ascii_case(name))
    }

    /// The span the robot is following now, if any.
    pub fn open(&self) -> Option<&Span> {
        self.spans.last().filter(|s| s.t_end.is_none())
    }

    /// The span whose fade-in window holds `t`: the corner into its first move is
    /// carried (partly) too, though its move began before.
    fn fading_at(&self, t: f64) -> Option<&Span> {
        self.spans.iter().rev().find(|s| s.fade.covers(t))
    }

    /// The fly-by point before a following began is final: the following fades in over
    /// its corner.
    pub fn begin_fade(&mut self, planned: &rapid_motion::plan::PlannedMove) {
        if let Some(span) = self.spans.last_mut().filter(|s| s.fade == Fade::Pending) {
            span.fade = Fade::after(planned);
        }
    }

    /// The last move of a following that fades out is final: the following ends with
    /// it, fading out over its corner.
    pub fn end_fade(&mut self, planned: &rapid_motion::plan::PlannedMove) {
        if let Some(span) = self.spans.last_mut().filter(|s| s.exit == Fade::Pending) {
            span.exit = Fade::before_end(planned);
            span.t_end = Some(planned.end);
        }
    }

    /// The span a move that started at `move_start` was planned in: moves planned while
    /// the robot followed an object move with it until it stopped following.
    pub fn span_of(&self, move_start: f64) -> Option<&Span> {
        const EPS: f64 = 1e-9;
        self.spans
            .iter()
            .rev()
            .find(|s| s.t_ref <= move_start + EPS && s.t_end.is_none_or(|end| move_start < end - EPS))
    }
}

impl super::robot::RobotState {
    /// Reads the conveyors' inputs from the I/O system's change log.
    pub fn refresh_conveyors(&mut self, io: Option<&rapid_io::IoSystem>) {
        let Some(io) = io else { return };
        for conveyor in &mut self.following.conveyors {
            conveyor.refresh(io);
        }
    }

    /// How the object the robot follows at `t` on a move that started at `move_start`
    /// has moved since the move was planned, in the robot's base frame; `eax` gives the
    /// external axes at a time.
    fn carried(&self, t: f64, move_start: f64, eax: impl Fn(f64) -> Option<Eax>) -> Option<Pose> {
        let world = self.carried_world(t, move_start, eax, true)?;
        Some(self.base_frame.inverse() * world * self.base_frame)
    }

    /// The same motion in the world frame; `robot`: as it carries the robot (faded in
    /// over the corner into a following), else as the object itself moved (for the
    /// moves made in its work object only).
    fn carried_world(&self, t: f64, move_start: f64, eax: impl Fn(f64) -> Option<Eax>, robot: bool) -> Option<Pose> {
        let span = match robot {
            true => self.following.span_of(move_start).or_else(|| self.following.fading_at(t))?,
            false => self.following.span_of(move_start)?,
        };
        let t = span.t_end.map_or(t, |end| t.min(end));
        let at = self.mover_at(&span.mover, t, eax)?;
        if !robot {
            return Some(span.mover.carry(&self.following.conveyors, &span.frames_ref, &at));
        }
        // While the following fades in, the robot is carried by a part of the travel;
        // while it fades out, the robot leaves the object for where it was planned to be.
        let leave = match span.exit {
            Fade::Window(..) => span.exit.weight(t),
            _ => 0.0,
        };
        let w = span.fade.weight(t);
        let at: MoverAt = std::array::from_fn(|k| {
            let faded_in = span.at_ref[k] + w * (at[k] - span.at_ref[k]);
            faded_in + leave * (span.at_ref[k] - faded_in)
        });
        Some(span.mover.carry(&self.following.conveyors, &span.at_ref, &at))
    }

    /// Where `mover` is at `t`: the conveyor object's distance from the sync switch, or
    /// the unit's axis values (`eax` gives the external axes at a time).
    pub(super) fn mover_at(&self, mover: &Mover, t: f64, eax: impl Fn(f64) -> Option<Eax>) -> Option<MoverAt> {
        match *mover {
            Mover::Conveyor { conveyor, object } => {
                let mut at = [0.0; 6];
                at[0] = self.following.conveyors[conveyor].position(t) - object;
                Some(at)
            }
            Mover::Unit { .. } => eax(t),
            Mover::Foreign { unit, .. } => self.foreign_eax_at(unit, t),
        }
    }

    /// Joints where the robot is at `t` when its planned `joints` are carried by the
    /// work object it follows; unchanged when it follows none.
    pub(super) fn tracked_joints(&mut self, t: f64, joints: Joints) -> Joints {
        if self.following.spans.is_empty() {
            return joints;
        }
        let start = self.move_start_at(t);
        let Some(carry) = self.carried(t, start, |at| self.eax_at(at)) else { return joints };
        let flange = carry * self.kin.forward(&joints);
        match self.kin.inverse_near(&flange, &joints) {
            Ok(shifted) => shifted,
            Err(_) => {
                self.following.unreachable.get_or_insert(t);
                joints
            }
        }
    }

    /// The start of the move the robot is on (or last made) at `t`, as `joints_at`
    /// chooses it.
    fn move_start_at(&self, t: f64) -> f64 {
        let t = self.pause.as_ref().map_or(t, |p| t.min(p.since));
        if self.planner.has_pending() && t > self.planner.time() {
            return self.planner.time();
        }
        match self.ahead.iter().find(|m| t <= m.end) {
            Some(m) => m.start,
            None => self.ahead.back().map_or(self.planner.time(), |m| m.start),
        }
    }

    /// A trace sample of `planned`, carried by the work object the robot followed then
    /// (and on a track, where the track had the robot then).
    pub fn tracked(&self, planned: &rapid_motion::plan::PlannedMove, sample: Sample) -> Sample {
        let sample = self.on_track(planned, sample);
        if self.following.spans.is_empty() {
            return sample;
        }
        self.carried_sample(planned, sample)
    }

    /// A sample of `planned` with its TCP and flange where the track had the robot's
    /// base at the sample's time (the move's frames have its base where the move ends),
    /// and its TCP speed in the world.
    fn on_track(&self, planned: &rapid_motion::plan::PlannedMove, mut sample: Sample) -> Sample {
        let Some((axis, dir)) = self.external.track() else { return sample };
        let dir = self.in_base(dir);
        let (Some(end), Some(now)) = (planned.eax_end(), planned.eax_at(sample.time)) else { return sample };
        let by = Translation3::from(dir * (now[axis] - end[axis]));
        sample.tcp = by * sample.tcp;
        sample.flange = by * sample.flange;
        // The TCP's world speed: a central difference of its world position.
        const H: f64 = 0.001;
        let (t1, t2) = ((sample.time - H).max(planned.start), (sample.time + H).min(planned.end));
        let world = |t: f64| {
            let track = planned.eax_at(t).map_or(0.0, |e| e[axis]);
            planned.sample(&self.kin, t).tcp.translation.vector + dir * track
        };
        if t2 - t1 > 1e-9 {
            sample.tcp_speed = (world(t2) - world(t1)).norm() / (t2 - t1);
        }
        sample
    }

    /// How the work object the robot followed on `planned` had moved at `t` since the
    /// move was planned (`None` when it followed none): a sample's TCP in that work
    /// object is its carried TCP brought back by this motion.
    pub fn carry_at(&self, planned: &rapid_motion::plan::PlannedMove, t: f64) -> Option<Pose> {
        self.carried_world(t, planned.start, |at| planned.eax_at(at), false)
    }

    /// Where the programmed point of a recorded move is when the robot passes it: a
    /// point in a work object that moves (a conveyor's, a unit's) is carried there by
    /// the object's travel since the move's frames were frozen.
    pub fn point_passed(&self, facts: &super::robot::MoveFacts) -> Pose {
        let moves = self.recorded.as_deref().unwrap_or(&[]);
        let Some(on) = moves.iter().rev().find(|m| m.start <= facts.passed) else { return facts.point };
        match self.carried_world(facts.passed, facts.start, |at| on.eax_at(at), false) {
            Some(carry) => carry * facts.point,
            None => facts.point,
        }
    }

    /// A sample carried by the work object the robot followed (unchanged when it
    /// followed none).
    pub(super) fn carried_sample(&self, planned: &rapid_motion::plan::PlannedMove, mut sample: Sample) -> Sample {
        let Some(by) = self.carried(sample.time, planned.start, |at| planned.eax_at(at)) else { return sample };
        sample.flange = by * sample.flange;
        sample.tcp = by * sample.tcp;
        if let Ok(joints) = self.kin.inverse_near(&sample.flange, &sample.joints) {
            sample.joints = joints;
        }
        sample
    }
}
