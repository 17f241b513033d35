//! Path planning and timing: a queue of moves (target, speed, zone) becomes
//! moves on a time axis with corner paths at fly-by points, and a sampler gives
//! joints, TCP pose and TCP speed at any time.
//!
//! The VM pushes each move instruction as it executes. A fly-by move's corner
//! can only be planned once the next move is known, so [`Planner::push`] hands
//! back the *previous* move, now final; [`Planner::flush`] ends the queue (the
//! last move stops; if it was a fly-by point that is a corner path failure).
//!
//! Timing model (reference motion.md §4): each path gets one speed cap — the
//! programmed TCP speed, the reorientation speed, and every axis's maximum
//! speed found by sampling the path with inverse kinematics — and a trapezoid
//! profile with constant acceleration. Joint moves are measured in a joint
//! metric where each axis is divided by its maximum speed, so the limiting axis
//! sets the pace and all axes start and stop together.
//!
//! For the VM: after a stop point the next instruction runs at the move's
//! `end` (settle included). After a fly-by point execution runs on; the next
//! move must be pushed before [`Planner::pending_stop_time`] or the VM flushes
//! (the robot stops there and the move reports `corner_path_failure`). When the
//! logic after a fly-by point runs (spec §2.3: about 0.1 s of planning plus the
//! servo lag before the zone, `zone_entry`) is the VM's choice.
//!
//! ```
//! # use rapid_motion::{Joints, Kinematics, Pose};
//! # struct Gantry;
//! # impl Kinematics for Gantry {
//! #     fn forward(&self, q: &Joints) -> Pose { Pose::translation(q[0], q[1], q[2]) }
//! #     fn inverse(&self, p: &Pose) -> Vec<Joints> {
//! #         let t = p.translation.vector;
//! #         vec![[t.x, t.y, t.z, 0.0, 0.0, 0.0]]
//! #     }
//! #     fn limits(&self) -> [(f64, f64); 6] { [(-1e4, 1e4); 6] }
//! #     fn max_speeds(&self) -> [f64; 6] { [1e4; 6] }
//! # }
//! use rapid_motion::plan::{AccelLimits, MoveRequest, Planner, SpeedData, Target, ZoneData, DEFAULT_STEP};
//! use rapid_motion::pose::pose;
//!
//! let robot = Gantry;
//! let mut planner = Planner::new([0.0; 6], AccelLimits::nominal(&robot.max_speeds()));
//! let v1000 = SpeedData::predefined("v1000").unwrap();
//! let (tool0, wobj) = (Pose::identity(), Pose::identity());
//! let mut moves = Vec::new();
//! for (x, zone) in [(100.0, "z10"), (200.0, "fine")] {
//!     let target = Target::Linear(pose([x, 50.0, 0.0], [1.0, 0.0, 0.0, 0.0]));
//!     let zone = ZoneData::predefined(zone).unwrap();
//!     moves.extend(planner.push(&robot, &MoveRequest { target, speed: v1000, zone, tool: tool0, held_object: None, wobj })?);
//! }
//! moves.extend(planner.flush());
//! let trace: Vec<_> = moves.iter().flat_map(|m| m.samples(&robot, DEFAULT_STEP)).collect();
//! assert!(moves[1].end > 0.0 && trace.iter().all(|s| s.tcp_speed <= 1000.0 + 1e-9));
//! # Ok::<(), rapid_motion::MotionError>(())
//! ```

mod continuity;
mod corner;
mod correct;
mod data;
mod external;
mod idle;
mod limits;
mod mount;
mod orient;
mod path;
mod profile;
mod rebase;
mod retime;
mod sample;
mod segment;
mod wrist;

pub use corner::CornerKind;
pub use correct::path_frame;
pub use data::{CircleOri, MotionSettings, SpeedData, ZoneData};
pub use limits::AccelLimits;
pub use mount::Mount;
pub use retime::{retime, Retiming};
pub use sample::{PlannedMove, Sample, DEFAULT_STEP};
pub use segment::{MoveRequest, Target};

use crate::external::{Eax, ExternalMove};
use crate::{Joints, Kinematics, MotionError};
use corner::Corner;
use orient::OriZone;
use profile::Profile;
use sample::{Piece, Span};
use segment::Prepared;

/// Plans a robot's moves one at a time, in program order.
#[derive(Debug, Clone)]
pub struct Planner {
    nominal: AccelLimits,
    settings: MotionSettings,
    /// Where the last pushed move ends (the start of the next).
    joints: Joints,
    /// When the pending move starts.
    time: f64,
    pending: Option<Pending>,
    /// Where the last pushed move leaves the external axes; `None` without any.
    eax: Option<Eax>,
}

/// A move pushed but not yet final: it waits for the next move to plan its
/// corner.
#[derive(Debug, Clone)]
struct Pending {
    prep: Prepared,
    /// Where on its path it starts (after the previous corner) and how fast.
    s_start: f64,
    v_start: f64,
    /// The previous corner's reorientation zone, reaching into this move.
    ori_in: Option<OriZone>,
    /// The part of its own profile already walked when the speed override changed
    /// under way (`retime.rs`): the rest is shaped from its end.
    head: Option<Profile>,
}

/// Where the next move takes over after a corner.
struct Handover {
    s_out: f64,
    v_out: f64,
    ori: Option<OriZone>,
}

impl Planner {
    /// A planner for a robot standing at `start` at time 0, with the robot's
    /// nominal accelerations (see [`AccelLimits::nominal`]).
    pub fn new(start: Joints, nominal: AccelLimits) -> Self {
        Planner { nominal, settings: MotionSettings::default(), joints: start, time: 0.0, pending: None, eax: None }
    }

    /// The settings (AccSet, VelSet, speed override) moves are planned with.
    pub fn settings(&self) -> &MotionSettings {
        &self.settings
    }

    /// Changes the settings for moves pushed from now on.
    pub fn set_settings(&mut self, settings: MotionSettings) {
        self.settings = settings;
    }

    /// The joint values the robot ends at once every pushed move has run.
    pub fn end_joints(&self) -> Joints {
        self.joints
    }

    /// Where the external axes are once every pushed move has run (`None`: the
    /// system has none).
    pub fn end_eax(&self) -> Option<Eax> {
        self.eax
    }

    /// The external axes stand at `eax` (at the start, or where a stop left them).
    pub fn set_eax(&mut self, eax: Option<Eax>) {
        self.eax = eax;
    }

    /// When the move still waiting for its successor starts; with none waiting,
    /// when the robot stands still at the end of the last move.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// When the waiting move would stand still at its end point if no move
    /// followed it: the latest a fly-by point's successor can be pushed before
    /// the robot would have to stop (a corner path failure).
    pub fn pending_stop_time(&self) -> Option<f64> {
        let p = self.pending.as_ref()?;
        let own = p.prep.limits.length - p.s_start;
        Some(self.time + p.own_profile(0.0, own).duration)
    }

    /// Whether a move waits for its successor.
    pub fn has_pending(&self) -> bool {
        self.pending.is_some()
    }

    /// Adds a move. Returns the previous move, now final, if there was one. On
    /// an error (unreachable target, zero speed, degenerate circle) nothing
    /// changes: the previous move still waits.
    pub fn push<K: Kinematics + ?Sized>(
        &mut self,
        kin: &K,
        request: &MoveRequest,
    ) -> Result<Option<PlannedMove>, MotionError> {
        self.push_with(kin, request, None)
    }

    /// [`Planner::push`] with the external axes' move: they go to `ext.to` along the
    /// arm's path (see `ExternalMove`).
    pub fn push_with<K: Kinematics + ?Sized>(
        &mut self,
        kin: &K,
        request: &MoveRequest,
        ext: Option<&ExternalMove>,
    ) -> Result<Option<PlannedMove>, MotionError> {
        let prep = segment::prepare(kin, request, &self.joints, &self.settings, &self.nominal, ext)?;
        self.joints = prep.end_joints;
        if let Some(ext) = ext {
            self.eax = Some(ext.to);
        }
        let Some(pending) = self.pending.take() else {
            self.pending = Some(Pending { prep, s_start: 0.0, v_start: 0.0, ori_in: None, head: None });
            return Ok(None);
        };
        // uncertain: the corner is walked as Paul's blend (constant acceleration
        // between the entry and exit velocities, motion.md §4.2); the
        // controller's own speed inside the corner is not published.
        let blend = corner::corner(kin, &pending.prep, &prep).and_then(|c| corner_speeds(&pending, c, &prep));
        let blend = blend.map(|b| Blend { eax_out: external::at_start_of(&prep, b.corner.s_out), ..b });
        let (planned, handover) = self.finalize(&pending, blend);
        self.pending = Some(match handover {
            Some(h) => Pending { prep, s_start: h.s_out, v_start: h.v_out, ori_in: h.ori, head: None },
            None => Pending { prep, s_start: 0.0, v_start: 0.0, ori_in: None, head: None },
        });
        Ok(Some(planned))
    }

    /// Moves the waiting move rigidly by `by` (a pose in the base frame), path and joints,
    /// with where it starts on its path and how fast kept (`rebase.rs`). Nothing changes
    /// on an error (the moved path leaves the robot's reach, a stationary tool).
    pub fn rebase_pending<K: Kinematics + ?Sized>(&mut self, kin: &K, by: &crate::Pose) -> Result<(), MotionError> {
        let Some(pending) = self.pending.as_ref() else { return Ok(()) };
        // The previous corner's reorientation zone reaches into the move with its old
        // orientation: a turn would break it.
        if pending.ori_in.is_some() && by.rotation.angle() > 1e-12 {
            return Err(MotionError::InvalidData("a move entered through a reorientation zone cannot be turned"));
        }
        let start = match &pending.prep.geom {
            path::Geometry::Joint { q0, .. } => *q0,
            _ => pending.prep.seeds.first().map_or(self.joints, |(_, q)| *q),
        };
        let (prep, _) = rebase::rebased(kin, &pending.prep, &start, by)?;
        self.joints = prep.end_joints;
        if let Some(pending) = self.pending.as_mut() {
            pending.prep = prep;
        }
        Ok(())
    }

    /// Ends the queue: the waiting move, if any, stops at its end point.
    pub fn flush(&mut self) -> Option<PlannedMove> {
        let pending = self.pending.take()?;
        let (mut planned, _) = self.finalize(&pending, None);
        planned.corner_path_failure = !pending.prep.zone.is_stop();
        Some(planned)
    }

    /// Times `pending`, ending in `blend` or in a stop. Returns the planned
    /// move and where on its path and how fast the next move takes over.
    fn finalize(&mut self, pending: &Pending, blend: Option<Blend>) -> (PlannedMove, Option<Handover>) {
        let limits = &pending.prep.limits;
        let Some(Blend { corner, v_in, v_out, eax_out }) = blend else {
            let own = pending.own_profile(0.0, limits.length - pending.s_start);
            return (self.place(pending, own, None), None);
        };
        let own_len = limits.length.min(corner.s_in) - pending.s_start;
        let own = pending.own_profile(v_in, own_len);
        let (rate_in, rate_out) = corner.path.rates(v_in * corner.scale_in, v_out * corner.scale_out);
        let handover = Handover { s_out: corner.s_out, v_out, ori: corner.path.ori_zone() };
        (self.place(pending, own, Some((corner, Profile::blend(rate_in, rate_out), eax_out))), Some(handover))
    }

    /// The waiting move as it would be if it stopped at its point: until it starts
    /// braking, the robot moves exactly as it will once its successor is known (the
    /// fly-by profile accelerates and cruises the same way and brakes later), so
    /// events placed from the move's start can be timed before the move is final.
    /// Returns the move and the time it starts braking.
    pub fn provisional(&self) -> Option<(PlannedMove, f64)> {
        let pending = self.pending.as_ref()?;
        let own = pending.own_profile(0.0, pending.prep.limits.length - pending.s_start);
        let braking = self.time + own.braking_start();
        Some((self.lay_out(pending, own, None), braking))
    }

    /// Lays the move's own profile and its corner's out on the time axis from
    /// the planner's clock, which then moves on to the move's end.
    fn place(&mut self, pending: &Pending, own: Profile, corner: Option<CornerPlan>) -> PlannedMove {
        let planned = self.lay_out(pending, own, corner);
        self.time = planned.end;
        planned
    }

    /// The move laid out on the time axis from the planner's clock.
    fn lay_out(&self, pending: &Pending, own: Profile, corner: Option<CornerPlan>) -> PlannedMove {
        let prep = &pending.prep;
        let start = self.time;
        let s0 = pending.s_start;
        let seeds = prep.seeds.iter().map(|(s, q)| (s - s0, *q)).collect();
        let ori_out = corner.as_ref().and_then(|(c, _, _)| c.path.ori_zone());
        let mut eax = prep
            .eax
            .as_ref()
            .map(|ext| Box::new(external::EaxTrack { ext: **ext, length: prep.limits.length, corner: None }));
        let piece = Piece::Own { geom: prep.geom.clone(), s0, ori_in: pending.ori_in, ori_out };
        let zone_entry = start + own.duration;
        let mut spans = vec![Span { piece, t0: start, seeds, profile: own }];
        let (mut end, mut corner_time, mut zone) = (zone_entry, 0.0, 0.0);
        match corner {
            Some((c, profile, eax_out)) => {
                (corner_time, zone) = (profile.duration, c.zone);
                if let Some(track) = &mut eax {
                    track.corner = eax_out.map(|out| (track.at(c.s_in), out));
                }
                end += corner_time;
                spans.push(Span { piece: Piece::Corner(c.path), t0: zone_entry, seeds: c.seeds, profile });
            }
            None if prep.zone.finep => end += prep.accel.settle,
            None => {}
        }
        PlannedMove {
            start,
            zone_entry,
            end,
            corner_time,
            zone,
            corner_path_failure: false,
            end_joints: prep.end_joints,
            spans,
            mount: prep.mount,
            eax,
        }
    }
}

/// A corner with the path speeds at its entry (in the incoming move's unit)
/// and its exit (in the outgoing move's).
struct Blend {
    corner: Corner,
    v_in: f64,
    v_out: f64,
    /// The external axes where the corner joins the next move.
    eax_out: Option<Eax>,
}

/// A corner laid out: its path, its speed profile and the external axes at its exit.
type CornerPlan = (Corner, Profile, Option<Eax>);

/// The speeds at a corner's entry and exit, or `None` when the corner would be
/// walked at no speed at all (the move then stops instead).
fn corner_speeds(pending: &Pending, c: Corner, next: &Prepared) -> Option<Blend> {
    // From where the robot is on it when it was re-timed under way, else its start.
    let (walked, v0) = pending.head.as_ref().map_or((0.0, pending.v_start), |h| (h.length, h.end_speed));
    let (cur, own) = (&pending.prep.limits, (c.s_in - pending.s_start - walked).max(0.0));
    // Entry: as fast as this move's cap, the corner and acceleration allow,
    // but never slower than braking at full deceleration from the start gives.
    let reach = (v0 * v0 + 2.0 * cur.acc * own).sqrt();
    let brake = (v0 * v0 - 2.0 * cur.dec * own).max(0.0).sqrt();
    let v_in = cur.cap.min(c.cap / c.scale_in).min(reach).max(brake);
    // Exit: the next move's own successor is not known yet, so it must still be
    // able to stop within what is left of it.
    let left = (next.limits.length - c.s_out).max(0.0);
    let v_out = next.limits.cap.min(c.cap / c.scale_out).min((2.0 * next.limits.dec * left).sqrt());
    (v_in + v_out > 1e-9).then_some(Blend { corner: c, v_in, v_out, eax_out: None })
}
