//! One move made ready for timing: its path, its length, and the speed and
//! acceleration it may use — programmed speeds, reorientation speed and the axis
//! speeds found by sampling the path with inverse kinematics.

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

use super::data::{CircleOri, MotionSettings, SpeedData, ZoneData};
use super::limits::AccelLimits;
use super::mount::Mount;
use super::path::{Geometry, Metric, OriLerp, OriMode, Point, EPS_DEG, EPS_TCP};
use super::profile::{PieceLimits, EPS_LEN};
use crate::external::ExternalMove;
use crate::{Joints, Kinematics, MotionError, Pose};

/// Where a move goes and how it interpolates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// MoveJ / MoveAbsJ: joint interpolation to these axis values (the VM has
    /// already chosen the IK branch by confdata for a MoveJ to a robtarget).
    Joints(Joints),
    /// MoveL: a straight TCP line to this TCP pose, in the robot base frame.
    Linear(Pose),
    /// MoveC: a circle through `via` to `to` (TCP poses, base frame). The
    /// orientation goes from the start to `to`'s; `via`'s is not used.
    Circular { via: Pose, to: Pose },
}

/// One move instruction as the planner needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoveRequest {
    pub target: Target,
    pub speed: SpeedData,
    pub zone: ZoneData,
    /// The tool frame (`tframe`): the TCP in the flange (`tool0`) frame; for a
    /// stationary tool (`held_object` given), the fixed TCP in the base frame.
    pub tool: Pose,
    /// A stationary tool: the work object the robot holds, its frame in the flange
    /// frame. Linear and circular targets are then TCP poses in that object frame.
    pub held_object: Option<Pose>,
    /// The work object's frame (user frame · object frame) in the base frame. The
    /// path does not depend on it (targets are in the base frame already); a corner
    /// between moves in different work objects is joint-interpolated (§2.2.3).
    pub wobj: Pose,
}

impl MoveRequest {
    /// How this move's path relates to the flange.
    pub fn mount(&self) -> Mount {
        match self.held_object {
            Some(object) => Mount::Stationary { tcp: self.tool, object },
            None => Mount::Held(self.tool),
        }
    }
}

/// A move ready for timing.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Prepared {
    pub(crate) geom: Geometry,
    pub(crate) limits: PieceLimits,
    pub(crate) zone: ZoneData,
    pub(crate) mount: Mount,
    /// The move's work object frame (see `MoveRequest::wobj`).
    pub(crate) wobj: Pose,
    pub(crate) end_joints: Joints,
    /// Joint values along a Cartesian path (path parameter, joints), which seed
    /// the inverse kinematics when the path is sampled.
    pub(crate) seeds: Vec<(f64, Joints)>,
    /// TCP distance to the nearest programmed neighbour along this move (mm):
    /// zones at either end may use at most half of it.
    pub(crate) room: f64,
    /// The accelerations this move was planned with (AccSet applied).
    pub(crate) accel: AccelLimits,
    pub(crate) max_speeds: [f64; 6],
    /// The external axes' move, when the system has external axes (boxed: moves
    /// without external axes stay small).
    pub(crate) eax: Option<Box<ExternalMove>>,
    /// Only the external axes move (the arm stands): the path is theirs, of unit length.
    pub(crate) axes_only: bool,
}

/// Most IK samples taken along one path to find its axis-speed limit.
const MAX_SAMPLES: usize = 48;

/// Makes `request` ready for timing, starting from `start` joints.
pub(crate) fn prepare<K: Kinematics + ?Sized>(
    kin: &K,
    request: &MoveRequest,
    start: &Joints,
    settings: &MotionSettings,
    nominal: &AccelLimits,
    ext: Option<&ExternalMove>,
) -> Result<Prepared, MotionError> {
    check_finite(request, start)?;
    // With `\T` the move's time takes the place of the programmed speeds.
    let speed = match settings.move_time {
        Some(_) => {
            SpeedData { v_tcp: f64::INFINITY, v_ori: f64::INFINITY, v_leax: f64::INFINITY, v_reax: f64::INFINITY }
        }
        None => settings.effective_speed(&request.speed),
    };
    let mut accel = nominal.sanitized().scaled(settings.acc_factor());
    if let Some(stop) = settings.stop_time.filter(|t| t.is_finite() && *t >= 0.0) {
        accel.settle = stop;
    }
    let max_speeds = kin.max_speeds().map(|v| if v.is_finite() && v > 0.0 { v } else { 1.0 });
    let limit = |l: Option<f64>| l.filter(|a| a.is_finite() && *a > 0.0).unwrap_or(f64::INFINITY);
    let (tcp_acc_max, tcp_dec_max) = (limit(settings.tcp_acc_max), limit(settings.tcp_dec_max));
    // A 7-axis arm's axis 7 moves with the path in eax_a: every kinematics call along
    // the path is given the external axes there.
    let ext7 = ext.filter(|_| kin.redundant()).copied();
    let ctx = Ctx { kin, mount: request.mount(), speed, accel, max_speeds, tcp_acc_max, tcp_dec_max, ext7 };
    let start_tcp = ctx.tcp(start, 0.0);
    let mut prepared = match request.target {
        Target::Joints(q1) => ctx.joint_move(start, q1)?,
        Target::Linear(to) => {
            let ori = OriLerp::fixed(start_tcp.rotation, to.rotation);
            let mut geom = Geometry::Line { p0: start_tcp.translation.vector, p1: to.translation.vector, ori };
            let room = (to.translation.vector - start_tcp.translation.vector).norm();
            if settings.sing_wrist {
                ctx.wrist_interpolation(&mut geom, start, &to)?;
            }
            ctx.cartesian_move(geom, start, room)?
        }
        Target::Circular { via, to } => {
            // On a moving track the circle is the world's: its points relative to the
            // base where the move starts (the targets are relative to where it ends).
            let travel = Vector3::from(settings.base_travel);
            let (p0, pc, p1) =
                (start_tcp.translation.vector, via.translation.vector + travel, to.translation.vector + travel);
            let ori = OriLerp::fixed(start_tcp.rotation, to.rotation);
            let mut geom = Geometry::arc(p0, pc, p1, ori)?;
            let via = tcp_pose(&pc, &via.rotation);
            circle_orientation(&mut geom, ori, &via, settings.circle_ori);
            geom.set_drift(travel);
            if settings.sing_wrist {
                ctx.wrist_interpolation(&mut geom, start, &to)?;
            }
            ctx.cartesian_move(geom, start, (pc - p0).norm().min((p1 - pc).norm()))?
        }
    };
    prepared.zone = request.zone;
    prepared.wobj = request.wobj;
    if let Some(ext) = ext {
        super::external::pace(&mut prepared, ext, &speed, settings.acc_factor())?;
        if prepared.axes_only && ext7.is_some() && !prepared.seeds.is_empty() {
            // A 7-axis arm's elbow turning about a standing TCP: its arm axes follow
            // (`ik_along`) and bound the pace as on any path.
            prepared.limits.cap = prepared.limits.cap.min(axis_cap(&prepared.seeds, &max_speeds));
        }
    }
    if let Some(time) = settings.move_time {
        let k = settings.speed_factor();
        if !(time.is_finite() && time > 0.0) || k <= 0.0 {
            return Err(MotionError::InvalidData("\\T is not a positive time"));
        }
        // The speed overrides stretch the time as they would slow the speeds.
        let timed = timed_speed(&prepared.limits, time / k);
        prepared.limits.cap = prepared.limits.cap.min(timed);
    }
    Ok(prepared)
}

/// A circle's orientation interpolation by CirPathMode.
fn circle_orientation(geom: &mut Geometry, fixed: OriLerp, via: &Pose, mode: CircleOri) {
    let ori = match mode {
        CircleOri::ObjectFrame => return,
        CircleOri::PathFrame => match (geom.arc_turn(), geom.arc_fraction(&via.translation.vector)) {
            (Some((normal, sweep)), Some(at)) => OriLerp::path_frame(fixed, normal, sweep, (&via.rotation, at)),
            (Some((normal, sweep)), None) => {
                OriLerp { mode: OriMode::PathFrame { normal, sweep, turns: 0.0 }, ..fixed }
            }
            _ => return,
        },
        CircleOri::CirPointOri => {
            let Some(at) = geom.arc_fraction(&via.translation.vector) else { return };
            OriLerp { mode: OriMode::ViaPoint { via: via.rotation, at }, ..fixed }
        }
    };
    geom.set_ori(ori);
}

/// The cruise speed at which a stop-to-stop trapezoid over the path takes `time`
/// seconds: `time = L/v + v/a`, the smaller root. A time shorter than the fastest
/// triangle profile (2·√(L/a)) gives that profile's peak: the move takes longer.
// uncertain: `\T` is met for the move as if it stopped at both ends; a corner path
// at a fly-by end shortens it a little, as it does any move.
pub(crate) fn timed_speed(limits: &PieceLimits, time: f64) -> f64 {
    let (l, a, d) = (limits.length, limits.acc, limits.dec);
    if l <= EPS_LEN {
        return limits.cap;
    }
    if a == d {
        let disc = a * a * time * time - 4.0 * a * l;
        if disc <= 0.0 {
            return (a * l).sqrt();
        }
        return (a * time - disc.sqrt()) / 2.0;
    }
    // time = L/v + v/(2a) + v/(2d): k·v² − time·v + L = 0 with k = 1/(2a) + 1/(2d).
    let k = 0.5 / a + 0.5 / d;
    let disc = time * time - 4.0 * k * l;
    if disc <= 0.0 {
        return (l / k).sqrt();
    }
    (time - disc.sqrt()) / (2.0 * k)
}

/// What every step of preparing a move needs.
struct Ctx<'k, K: Kinematics + ?Sized> {
    kin: &'k K,
    mount: Mount,
    speed: SpeedData,
    accel: AccelLimits,
    max_speeds: [f64; 6],
    /// PathAccLim/WorldAccLim: the TCP's acceleration and braking on the path, mm/s².
    tcp_acc_max: f64,
    tcp_dec_max: f64,
    /// The external axes' move of a 7-axis arm (its axis 7 in eax_a); `None` otherwise.
    ext7: Option<ExternalMove>,
}

impl<K: Kinematics + ?Sized> Ctx<'_, K> {
    /// The path pose for `joints` a fraction `f` along the move (where a 7-axis arm's
    /// axis 7 is then).
    fn tcp(&self, joints: &Joints, f: f64) -> Pose {
        let flange = match &self.ext7 {
            Some(ext) => self.kin.forward_at(joints, &ext.at(f)),
            None => self.kin.forward(joints),
        };
        self.mount.path_pose(&flange)
    }

    fn prepared(&self, geom: Geometry, limits: PieceLimits, end_joints: Joints, room: f64) -> Prepared {
        Prepared {
            geom,
            limits,
            zone: ZoneData::FINE,
            mount: self.mount,
            wobj: Pose::identity(),
            end_joints,
            seeds: Vec::new(),
            room,
            accel: self.accel,
            max_speeds: self.max_speeds,
            eax: None,
            axes_only: false,
        }
    }

    /// MoveJ / MoveAbsJ: the limiting axis sets the pace, and the TCP's straight
    /// distance and the reorientation at the programmed speeds bound it too.
    /// uncertain: how the controller turns v_tcp into a joint move's pace (the
    /// manual: the TCP speed "cannot be the programmed value"); we bound the
    /// move's cruise time by chord / v_tcp and angle / v_ori.
    fn joint_move(&self, q0: &Joints, q1: Joints) -> Result<Prepared, MotionError> {
        check_limits(&self.kin.limits(), &q1)?;
        let weights = self.max_speeds.map(|v| 1.0 / v);
        let geom = Geometry::Joint { q0: *q0, q1, weights };
        let length = geom.length();
        let (tcp0, tcp1) = (self.tcp(q0, 0.0), self.tcp(&q1, 1.0));
        let room = (tcp1.translation.vector - tcp0.translation.vector).norm();
        if length <= EPS_LEN {
            return Ok(self.prepared(geom, PieceLimits { length: 0.0, cap: 1.0, acc: 1.0, dec: 1.0 }, q1, room));
        }
        // Direction in the joint metric; |dir_j| · (ds/dt) is axis j's speed as a
        // fraction of its maximum.
        let dir: [f64; 6] = std::array::from_fn(|j| (q1[j] - q0[j]) * weights[j] / length);
        let mut cap = 1.0 / dir.iter().fold(0.0f64, |m, d| m.max(d.abs()));
        let angle = tcp0.rotation.angle_to(&tcp1.rotation).to_degrees();
        cap = cap.min(time_cap(length, room, self.speed.v_tcp, EPS_TCP, "v_tcp is zero for a move of the TCP")?);
        cap = cap.min(time_cap(length, angle, self.speed.v_ori, EPS_DEG, "v_ori is zero for a reorientation")?);
        let acc = (0..6)
            .filter(|&j| dir[j] != 0.0)
            .map(|j| self.accel.joint[j] * weights[j] / dir[j].abs())
            .fold(f64::INFINITY, f64::min);
        Ok(self.prepared(geom, PieceLimits { length, cap, acc, dec: acc }, q1, room))
    }

    /// SingArea\Wrist: the wrist axes go straight in joint space from the start's
    /// to those of the end's solution nearest the start (a held tool only; a
    /// stationary tool's path keeps its orientation).
    fn wrist_interpolation(&self, geom: &mut Geometry, start: &Joints, to: &Pose) -> Result<(), MotionError> {
        if !matches!(self.mount, Mount::Held(_)) {
            return Ok(());
        }
        let end = match &self.ext7 {
            Some(ext) => self.kin.inverse_near_at(&self.mount.flange(to), start, &ext.to)?,
            None => self.kin.inverse_near(&self.mount.flange(to), start)?,
        };
        let Some(ori) = geom.ori().copied() else { return Ok(()) };
        let (from, to) = ([start[3], start[4], start[5]], [end[3], end[4], end[5]]);
        geom.set_ori(OriLerp { mode: OriMode::Wrist { from, to }, ..ori });
        Ok(())
    }

    /// MoveL / MoveC: TCP speed, reorientation speed and every axis's speed
    /// (sampled with IK along the path) bound the path speed.
    fn cartesian_move(&self, geom: Geometry, q0: &Joints, room: f64) -> Result<Prepared, MotionError> {
        let length = geom.length();
        let angle = geom.ori().map_or(0.0, OriLerp::angle);
        let seeds = ik_along(self.kin, &geom, &self.mount, q0, self.ext7.as_ref())?;
        let end_joints = seeds.last().map_or(*q0, |(_, q)| *q);
        if length <= EPS_LEN {
            let limits = PieceLimits { length: 0.0, cap: 1.0, acc: 1.0, dec: 1.0 };
            return Ok(Prepared { seeds, ..self.prepared(geom, limits, end_joints, room) });
        }
        let (cap, acc) = match geom.metric() {
            Metric::Deg => {
                if self.speed.v_ori <= 0.0 {
                    return Err(MotionError::InvalidData("v_ori is zero for a reorientation"));
                }
                (self.speed.v_ori, self.accel.ori)
            }
            _ => {
                if self.speed.v_tcp <= 0.0 {
                    return Err(MotionError::InvalidData("v_tcp is zero for a move of the TCP"));
                }
                // Reorientation at v_ori over the same time bounds the TCP speed.
                let ori_cap = time_cap(length, angle, self.speed.v_ori, EPS_DEG, "v_ori is zero for a reorientation")?;
                let ori_acc = if angle > EPS_DEG { self.accel.ori * length / angle } else { f64::INFINITY };
                (self.speed.v_tcp.min(ori_cap), self.accel.tcp.min(ori_acc))
            }
        };
        let cap = cap.min(axis_cap(&seeds, &self.max_speeds));
        // PathAccLim/WorldAccLim bound the TCP's acceleration and braking on the path.
        let (dec, acc) = match geom.metric() {
            Metric::Mm => (acc.min(self.tcp_dec_max), acc.min(self.tcp_acc_max)),
            _ => (acc, acc),
        };
        Ok(Prepared { seeds, ..self.prepared(geom, PieceLimits { length, cap, acc, dec }, end_joints, room) })
    }
}

/// The speed (in a path's own unit) at which `amount` (mm or °) is covered at
/// `speed` over a path of `length`: no bound when nothing of it moves.
fn time_cap(length: f64, amount: f64, speed: f64, eps: f64, zero: &'static str) -> Result<f64, MotionError> {
    if amount <= eps {
        return Ok(f64::INFINITY);
    }
    if speed.is_nan() || speed <= 0.0 {
        return Err(MotionError::InvalidData(zero));
    }
    Ok(length * speed / amount)
}

/// Joint values at evenly spaced points along a Cartesian path, each solved
/// near the one before, with points added between two whose axes differ much until
/// the joints are seen to change continuously (`continuity.rs`); the first is `q0`
/// itself. A jump to another solution branch is an error. `ext7` is a 7-axis arm's
/// external axes' move: axis 7 (eax_a) goes along in proportion to the path.
pub(crate) fn ik_along<K: Kinematics + ?Sized>(
    kin: &K,
    geom: &Geometry,
    mount: &Mount,
    q0: &Joints,
    ext7: Option<&ExternalMove>,
) -> Result<Vec<(f64, Joints)>, MotionError> {
    let length = geom.length();
    // A 7-axis arm turning its elbow about a standing TCP: the path is the external
    // axes' own, of unit length (`external::pace`), and the arm follows axis 7 along it.
    let turn7 = ext7.map_or(0.0, |e| (e.to[0] - e.from[0]).abs());
    let elbow_only = length <= EPS_LEN && turn7 > 1e-9;
    let span = if elbow_only { 1.0 } else { length };
    let solve = |s: f64, seed: &Joints| match ext7 {
        Some(ext) => {
            let f = if span > EPS_LEN { s / span } else { 1.0 };
            let at = if elbow_only { geom.at(length) } else { geom.at(s) };
            solve_at(&crate::kinematics::AtAxes { kin, eax: ext.at(f) }, &at, mount, seed)
        }
        None => solve_at(kin, &geom.at(s), mount, seed),
    };
    let angle = geom.ori().map_or(0.0, OriLerp::angle);
    let tcp_len = match geom.metric() {
        Metric::Mm => length,
        _ => 0.0,
    };
    // About one sample per 20 mm or 5° (of the TCP, or of axis 7 turning alone), within
    // bounds.
    let wanted = (tcp_len / 20.0).ceil() + (angle / 5.0).ceil() + if elbow_only { (turn7 / 5.0).ceil() } else { 0.0 };
    let n = if wanted.is_finite() { (wanted as usize).clamp(2, MAX_SAMPLES) } else { 2 };
    let mut seeds = Vec::with_capacity(n + 1);
    seeds.push((0.0, *q0));
    let mut seed = *q0;
    let mut budget = super::continuity::MAX_ADDED;
    for i in 1..=n {
        let s_prev = span * (i - 1) as f64 / n as f64;
        let s = span * i as f64 / n as f64;
        let q = solve(s, &seed)?;
        seed = super::continuity::bridge((kin, &solve), (s_prev, seed), (s, q), &mut seeds, &mut budget)?;
    }
    Ok(seeds)
}

/// The joints that put the TCP at `point`, nearest to `seed`.
pub(crate) fn solve_at<K: Kinematics + ?Sized>(
    kin: &K,
    point: &Point,
    mount: &Mount,
    seed: &Joints,
) -> Result<Joints, MotionError> {
    match point {
        Point::Joints(q) => Ok(*q),
        Point::Tcp(p, r) => kin.inverse_near(&mount.flange(&tcp_pose(p, r)), seed),
        Point::Wrist(p, wrist) => match mount {
            Mount::Held(tool) => super::wrist::arm_for(kin, tool, p, *wrist, seed),
            // The planner gives a stationary tool no wrist interpolation.
            Mount::Stationary { .. } => Err(MotionError::InvalidData("SingArea\\Wrist with a stationary tool")),
        },
    }
}

/// A pose from a position and a rotation.
pub(crate) fn tcp_pose(p: &Vector3<f64>, r: &UnitQuaternion<f64>) -> Pose {
    Isometry3::from_parts(Translation3::from(*p), *r)
}

/// The highest path speed at which no axis exceeds its maximum between
/// consecutive samples.
pub(crate) fn axis_cap(seeds: &[(f64, Joints)], max_speeds: &[f64; 6]) -> f64 {
    let mut cap = f64::INFINITY;
    for pair in seeds.windows(2) {
        let ((s0, q0), (s1, q1)) = (pair[0], pair[1]);
        for j in 0..6 {
            let dq = (q1[j] - q0[j]).abs();
            if dq > 1e-12 {
                cap = cap.min(max_speeds[j] * (s1 - s0) / dq);
            }
        }
    }
    cap
}

pub(crate) fn check_limits(limits: &[(f64, f64); 6], q: &Joints) -> Result<(), MotionError> {
    match (0..6).find(|&j| !(q[j] >= limits[j].0 - 1e-9 && q[j] <= limits[j].1 + 1e-9)) {
        Some(j) => Err(MotionError::JointLimit { axis: j + 1 }),
        None => Ok(()),
    }
}

fn check_finite(request: &MoveRequest, start: &Joints) -> Result<(), MotionError> {
    let pose_ok = |p: &Pose| p.translation.vector.iter().chain(p.rotation.coords.iter()).all(|x| x.is_finite());
    let target_ok = match &request.target {
        Target::Joints(q) => q.iter().all(|x| x.is_finite()),
        Target::Linear(to) => pose_ok(to),
        Target::Circular { via, to } => pose_ok(via) && pose_ok(to),
    };
    if !target_ok || !request.mount().is_finite() || !start.iter().all(|x| x.is_finite()) {
        return Err(MotionError::InvalidData("a target, tool or joint value is not a finite number"));
    }
    Ok(())
}
