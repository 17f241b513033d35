//! A planned move on the time axis, and its sampler: joint values, TCP pose and
//! TCP speed at any time, or on a fixed grid (the controller's 4 ms).

use super::corner::{nearest_seed, CornerPath};
use super::orient::OriZone;
use super::path::{Geometry, Metric, Point};
use super::profile::Profile;
use super::segment::{solve_at, tcp_pose};
use crate::{Joints, Kinematics, Pose};

/// The controller's sample period, s.
pub const DEFAULT_STEP: f64 = 0.004;

/// Most samples one call to [`PlannedMove::samples`] yields (a day at 4 ms):
/// a bound on a caller's mistaken step.
const MAX_SAMPLES: u64 = 21_600_000;

/// One move's timing and path, from the end of the previous move (the exit of
/// the corner before it, or its stop) to where the next move takes over.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedMove {
    /// When the move starts, s on the planner's time axis.
    pub start: f64,
    /// When the TCP enters the corner zone at the end of this move; for a stop
    /// point, when the robot stands still.
    pub zone_entry: f64,
    /// When the next move takes over: the corner's exit, or the end of the stop
    /// (with the settle time of a `fine` point).
    pub end: f64,
    /// How long the corner path took, s (0 for a stop point).
    pub corner_time: f64,
    /// The zone used, mm: pzone_tcp reduced to half the distance to either
    /// neighbour; 0 for a stop point.
    pub zone: f64,
    /// The move was programmed as a fly-by point but no next move was known in
    /// time, so it stopped ("Corner path failure").
    pub corner_path_failure: bool,
    /// Joint values at the programmed end point.
    pub end_joints: Joints,
    pub(crate) spans: Vec<Span>,
    pub(crate) mount: super::Mount,
    /// The external axes' track, when the system has external axes.
    // Boxed: most systems have no external axes, and moves are cloned often.
    pub(crate) eax: Option<Box<super::external::EaxTrack>>,
}

/// The robot at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub time: f64,
    pub joints: Joints,
    /// The TCP in the robot base frame.
    pub tcp: Pose,
    /// The flange (`tool0`) in the robot base frame.
    pub flange: Pose,
    /// TCP speed, mm/s (for a stationary tool: of the TCP over the held work object).
    pub tcp_speed: f64,
}

/// A stretch of path with its own speed profile.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Span {
    pub(crate) piece: Piece,
    pub(crate) t0: f64,
    pub(crate) profile: Profile,
    /// Joint values along the piece, keyed by the piece's own path parameter.
    pub(crate) seeds: Vec<(f64, Joints)>,
}

/// What a span walks along.
// A move holds at most two pieces, so their size does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Piece {
    /// The move's own path, from path parameter `s0` on, its orientation
    /// blended with the previous and the next move's in their reorientation
    /// zones.
    Own {
        geom: Geometry,
        s0: f64,
        ori_in: Option<OriZone>,
        ori_out: Option<OriZone>,
    },
    Corner(CornerPath),
}

impl PlannedMove {
    /// What the move's corner path blends, when it ends in one.
    pub fn corner_kind(&self) -> Option<super::CornerKind> {
        self.spans.iter().find_map(|span| match &span.piece {
            Piece::Corner(path) => Some(path.kind()),
            Piece::Own { .. } => None,
        })
    }

    /// How long the move takes, s.
    pub fn duration(&self) -> f64 {
        self.end - self.start
    }

    /// The robot at time `t` (clamped to the move).
    pub fn sample<K: Kinematics + ?Sized>(&self, kin: &K, t: f64) -> Sample {
        let t = if t.is_finite() { t.clamp(self.start, self.end) } else { self.start };
        let span = self.spans.iter().rev().find(|s| s.t0 <= t).or(self.spans.first());
        let Some(span) = span else {
            let flange = kin.forward(&self.end_joints);
            let tcp = self.mount.tcp(&flange);
            return Sample { time: t, joints: self.end_joints, tcp, flange, tcp_speed: 0.0 };
        };
        let (s, v) = span.profile.at(t - span.t0);
        let seed = nearest_seed(&span.seeds, s).unwrap_or(self.end_joints);
        if kin.redundant() {
            // A 7-axis arm: axis 7 is where the external axes' track has it now.
            if let Some(eax) = self.eax_at(t) {
                return self.sample_on(&crate::kinematics::AtAxes { kin, eax }, t, span, (s, v), &seed);
            }
        }
        self.sample_on(kin, t, span, (s, v), &seed)
    }

    /// The robot at time `t`, path parameter `s` of `span` at path speed `v`.
    fn sample_on<K: Kinematics + ?Sized>(
        &self,
        kin: &K,
        t: f64,
        span: &Span,
        (s, v): (f64, f64),
        seed: &Joints,
    ) -> Sample {
        let seed = *seed;
        let (joints, flange, tcp) = self.locate(kin, span, s, &seed);
        let tcp_speed = match &span.piece {
            Piece::Corner(path) => match path {
                CornerPath::Tcp { curve, .. } | CornerPath::Wrist { curve, .. } => v * curve.speed(s),
                CornerPath::Joint { .. } => v * self.tcp_per_unit(kin, span, s, &seed),
                // The TCP stands while the external axes or the orientation blend.
                CornerPath::Axes { .. } | CornerPath::Ori { .. } => 0.0,
            },
            Piece::Own { geom, .. } => match geom.metric() {
                Metric::Mm => v,
                Metric::Deg => 0.0,
                Metric::Joint => v * self.tcp_per_unit(kin, span, s, &seed),
            },
        };
        Sample { time: t, joints, tcp, flange, tcp_speed }
    }

    /// Samples at every multiple of `step` in `start..end`, so consecutive moves
    /// share one grid. Empty when `step` is not a positive number.
    pub fn samples<'a, K: Kinematics + ?Sized>(&'a self, kin: &'a K, step: f64) -> impl Iterator<Item = Sample> + 'a {
        self.samples_in(kin, step, 0..self.sample_count(step))
    }

    /// The samples numbered `range` of [`PlannedMove::samples`], each computed alone:
    /// a long trace is rendered in pieces.
    pub fn samples_in<'a, K: Kinematics + ?Sized>(
        &'a self,
        kin: &'a K,
        step: f64,
        range: std::ops::Range<u64>,
    ) -> impl Iterator<Item = Sample> + 'a {
        range.map(move |k| self.sample(kin, self.sample_time(step, k)))
    }

    /// How many samples [`PlannedMove::samples`] gives.
    pub fn sample_count(&self, step: f64) -> u64 {
        let valid = step.is_finite() && step > 0.0 && self.end.is_finite();
        let (first, last) = if valid { ((self.start / step).ceil(), (self.end / step).ceil()) } else { (0.0, 0.0) };
        (last - first).clamp(0.0, MAX_SAMPLES as f64) as u64
    }

    /// The time of sample `k` of [`PlannedMove::samples`].
    pub fn sample_time(&self, step: f64, k: u64) -> f64 {
        ((self.start / step).ceil() + k as f64) * step
    }

    /// Joints, flange and TCP (base frame) at path parameter `s` of `span`.
    fn locate<K: Kinematics + ?Sized>(&self, kin: &K, span: &Span, s: f64, seed: &Joints) -> (Joints, Pose, Pose) {
        match span.piece.at(s) {
            Point::Joints(q) => {
                let flange = kin.forward(&q);
                (q, flange, self.mount.tcp(&flange))
            }
            point @ Point::Wrist(..) => {
                // The arm is solved iteratively: start it between the samples around.
                let near = interpolated_seed(&span.seeds, s).unwrap_or(*seed);
                let joints = solve_at(kin, &point, &self.mount, &near).unwrap_or(*seed);
                let flange = kin.forward(&joints);
                (joints, flange, self.mount.tcp(&flange))
            }
            point @ Point::Tcp(p, r) => {
                let joints = solve_at(kin, &point, &self.mount, seed).unwrap_or(*seed);
                let path = tcp_pose(&p, &r);
                let flange = self.mount.flange(&path);
                // With a held tool the path point is the TCP itself.
                let tcp = match self.mount {
                    super::Mount::Held(_) => path,
                    super::Mount::Stationary { tcp, .. } => tcp,
                };
                (joints, flange, tcp)
            }
        }
    }

    /// TCP millimetres per unit of a joint-space path parameter, by a central
    /// difference around `s`.
    fn tcp_per_unit<K: Kinematics + ?Sized>(&self, kin: &K, span: &Span, s: f64, seed: &Joints) -> f64 {
        let len = span.profile.length;
        let h = (len * 1e-4).max(1e-9);
        let (lo, hi) = ((s - h).max(0.0), (s + h).min(len));
        if hi <= lo {
            return 0.0;
        }
        // The path pose: the TCP, or for a stationary tool the TCP over the object.
        let (_, a, _) = self.locate(kin, span, lo, seed);
        let (_, b, _) = self.locate(kin, span, hi, seed);
        let (a, b) = (self.mount.path_pose(&a), self.mount.path_pose(&b));
        (b.translation.vector - a.translation.vector).norm() / (hi - lo)
    }
}

/// The joints between the two samples around path parameter `s`, in proportion.
fn interpolated_seed(seeds: &[(f64, Joints)], s: f64) -> Option<Joints> {
    let after = seeds.partition_point(|(at, _)| *at < s);
    let ((s0, q0), (s1, q1)) = (seeds.get(after.checked_sub(1)?)?, seeds.get(after)?);
    let f = if s1 > s0 { ((s - s0) / (s1 - s0)).clamp(0.0, 1.0) } else { 0.0 };
    Some(std::array::from_fn(|j| q0[j] + f * (q1[j] - q0[j])))
}

impl Piece {
    fn at(&self, s: f64) -> Point {
        match self {
            Piece::Own { geom, s0, ori_in, ori_out } => {
                let s = s0 + s;
                match geom.at(s) {
                    Point::Tcp(p, r) => {
                        let out = ori_out.and_then(|z| Some(z.at(z.progress_before(s)?)));
                        let into = ori_in.and_then(|z| Some(z.at(z.progress_after(s)?)));
                        Point::Tcp(p, out.or(into).unwrap_or(r))
                    }
                    point => point,
                }
            }
            Piece::Corner(path) => path.at(s),
        }
    }
}
