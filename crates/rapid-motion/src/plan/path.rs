//! Path geometry: straight TCP lines, circle arcs and joint-space lines, each
//! measured by its own path parameter, and the quadratic Bézier (parabola) that
//! corner paths use, in TCP space or joint space.

use nalgebra::{UnitQuaternion, Vector3};

use crate::{Joints, MotionError};

/// TCP travel below this (mm) counts as no TCP motion: the move is a pure
/// reorientation, measured in degrees.
pub(crate) const EPS_TCP: f64 = 1e-3;
/// Reorientation below this (°) counts as none.
pub(crate) const EPS_DEG: f64 = 1e-6;

/// The unit a path parameter is measured in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Metric {
    /// Millimetres of TCP travel.
    Mm,
    /// Degrees of reorientation (the TCP stands still).
    Deg,
    /// Joint space, each axis divided by its maximum speed: the unit is the
    /// second an axis at full speed needs.
    Joint,
}

/// The orientation interpolation of a Cartesian move: slerp from `from` to
/// `to` over the move's fraction, in one of the ways CirPathMode chooses for a
/// circle (a line always slerps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct OriLerp {
    pub(crate) from: UnitQuaternion<f64>,
    pub(crate) to: UnitQuaternion<f64>,
    pub(crate) mode: OriMode,
}

/// How a circle's orientation is interpolated (CirPathMode).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum OriMode {
    /// In the fixed (object) frame: `\ObjectFrame`, and every straight line.
    Fixed,
    /// In the path frame, which turns with the circle's tangent by `sweep`
    /// radians about the circle's `normal` (`\PathFrame`, the default): the tool's
    /// orientation relative to the path goes from the start's to the end's, with
    /// `turns` whole turns about the normal added on the way (−1, 0 or 1): the way round
    /// the circle point's orientation picks (`path_frame`).
    PathFrame { normal: nalgebra::Unit<Vector3<f64>>, sweep: f64, turns: f64 },
    /// Through the circle point's orientation `via`, reached at fraction `at`
    /// (`\CirPointOri`).
    ViaPoint { via: UnitQuaternion<f64>, at: f64 },
    /// SingArea\Wrist: the wrist axes (4, 5, 6) go straight in joint space from
    /// `from` to `to`; the orientation is what they give (`wrist.rs`). The slerp
    /// from `from`'s orientation to `to`'s stands for it where only a nominal one
    /// is needed (the reorientation angle).
    Wrist { from: [f64; 3], to: [f64; 3] },
}

/// Samples of a non-linear interpolation used to measure its rotation.
const ORI_STEPS: usize = 16;

impl OriLerp {
    /// Slerp from `from` to `to` in the fixed frame.
    pub(crate) fn fixed(from: UnitQuaternion<f64>, to: UnitQuaternion<f64>) -> OriLerp {
        OriLerp { from, to, mode: OriMode::Fixed }
    }

    /// `\PathFrame` on a circle turning `sweep` about `normal`, passing the circle point
    /// (orientation `via`) at fraction `at`. Relative to the path the orientation goes the
    /// short way from the start's to the end's; on a circle of more than half a turn that
    /// way and the path's own turn can add up to a whole turn of the tool. The circle
    /// point's orientation picks the way round (motion.md: it "only picks the direction
    /// of reorientation"): the one of −1, 0 or 1 added turns that passes nearest to it.
    // uncertain: the controller's exact rule; a tool that keeps its orientation (start,
    // circle point and end alike) keeps it all the way round, as on the controller.
    pub(crate) fn path_frame(
        fixed: OriLerp,
        normal: nalgebra::Unit<Vector3<f64>>,
        sweep: f64,
        via: (&UnitQuaternion<f64>, f64),
    ) -> OriLerp {
        let with = |turns: f64| OriLerp { mode: OriMode::PathFrame { normal, sweep, turns }, ..fixed };
        let miss = |turns: f64| with(turns).at(via.1).angle_to(via.0);
        // Ties keep no added turn.
        let turns =
            [0.0, -1.0, 1.0].into_iter().fold(0.0, |best, t| if miss(t) < miss(best) - 1e-9 { t } else { best });
        with(turns)
    }

    pub(crate) fn at(&self, fraction: f64) -> UnitQuaternion<f64> {
        let f = if fraction.is_finite() { fraction.clamp(0.0, 1.0) } else { 0.0 };
        match self.mode {
            OriMode::Fixed | OriMode::Wrist { .. } => slerp(&self.from, &self.to, f),
            OriMode::PathFrame { normal, sweep, turns } => {
                // R(f) = Rn((sweep + 2π·turns)·f) · slerp(R0, Rn(−sweep)·R1, f): at f = 1
                // the turns cancel, and a tool that turns with the path keeps its
                // orientation relative to the tangent all the way.
                let turn = |angle: f64| UnitQuaternion::from_axis_angle(&normal, angle);
                let around = sweep + std::f64::consts::TAU * turns;
                turn(around * f) * slerp(&self.from, &(turn(-sweep) * self.to), f)
            }
            OriMode::ViaPoint { via, at } if at > 0.0 && at < 1.0 => {
                if f <= at {
                    slerp(&self.from, &via, f / at)
                } else {
                    slerp(&via, &self.to, (f - at) / (1.0 - at))
                }
            }
            OriMode::ViaPoint { .. } => slerp(&self.from, &self.to, f),
        }
    }

    /// The reorientation angle, degrees: for a slerp the angle between the ends;
    /// otherwise the rotation summed over small steps (the planner bounds the
    /// move's time by it and v_ori).
    pub(crate) fn angle(&self) -> f64 {
        match self.mode {
            OriMode::Fixed | OriMode::Wrist { .. } => self.from.angle_to(&self.to).to_degrees(),
            _ => {
                let mut total = 0.0;
                let mut last = self.at(0.0);
                for k in 1..=ORI_STEPS {
                    let next = self.at(k as f64 / ORI_STEPS as f64);
                    total += last.angle_to(&next);
                    last = next;
                }
                total.to_degrees()
            }
        }
    }
}

/// Slerp that never fails: for opposite quaternions at half way the start is as
/// good an answer as any.
fn slerp(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>, f: f64) -> UnitQuaternion<f64> {
    a.try_slerp(b, f, 1e-12).unwrap_or(*a)
}

/// One move's path.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Geometry {
    /// A straight TCP line (MoveL), orientation slerped along it.
    Line { p0: Vector3<f64>, p1: Vector3<f64>, ori: OriLerp },
    /// A circle arc (MoveC) from `center + radius·e1`, turning towards `e2`
    /// through `sweep` radians; `drift` is how far a track carries the robot's base
    /// over the move: the path relative to the base is the arc less that much of the
    /// drift as the move has gone (zero without a moving track).
    Arc {
        center: Vector3<f64>,
        radius: f64,
        e1: Vector3<f64>,
        e2: Vector3<f64>,
        sweep: f64,
        ori: OriLerp,
        drift: Vector3<f64>,
    },
    /// A straight line in joint space (MoveJ, MoveAbsJ); `weights` are the
    /// inverse axis speeds that define the joint metric.
    Joint { q0: Joints, q1: Joints, weights: [f64; 6] },
}

/// A point on a path: a TCP pose in the base frame, joint values, or (SingArea\Wrist)
/// a TCP position with the wrist axes' values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Point {
    Tcp(Vector3<f64>, UnitQuaternion<f64>),
    Joints(Joints),
    Wrist(Vector3<f64>, [f64; 3]),
}

impl Geometry {
    /// The circle arc from `start` through `via` to `end`, or why there is none.
    pub(crate) fn arc(
        start: Vector3<f64>,
        via: Vector3<f64>,
        end: Vector3<f64>,
        ori: OriLerp,
    ) -> Result<Geometry, MotionError> {
        let (a, b) = (via - start, end - start);
        let n = a.cross(&b);
        let scale = a.norm() * b.norm();
        let coincident = [a.norm(), b.norm(), (end - via).norm()].iter().any(|d| d.is_nan() || *d <= EPS_TCP);
        // A sine of 1e-6 between the chords is a radius of kilometres: collinear.
        let area = n.norm();
        if coincident || area.is_nan() || area <= 1e-6 * scale {
            return Err(MotionError::DegenerateCircle);
        }
        let offset = (a.norm_squared() * b.cross(&n) + b.norm_squared() * n.cross(&a)) / (2.0 * n.norm_squared());
        let center = start + offset;
        let radius = offset.norm();
        let e1 = -offset / radius;
        let e2 = n.normalize().cross(&e1);
        let rel = end - center;
        let mut sweep = rel.dot(&e2).atan2(rel.dot(&e1));
        if sweep <= 0.0 {
            sweep += std::f64::consts::TAU;
        }
        Ok(Geometry::Arc { center, radius, e1, e2, sweep, ori, drift: Vector3::zeros() })
    }

    /// How the path parameter is measured.
    pub(crate) fn metric(&self) -> Metric {
        match self {
            Geometry::Line { p0, p1, .. } if (p1 - p0).norm() <= EPS_TCP => Metric::Deg,
            Geometry::Line { .. } | Geometry::Arc { .. } => Metric::Mm,
            Geometry::Joint { .. } => Metric::Joint,
        }
    }

    /// The path length in its metric.
    pub(crate) fn length(&self) -> f64 {
        match self {
            Geometry::Line { p0, p1, ori } => match self.metric() {
                Metric::Deg => ori.angle(),
                _ => (p1 - p0).norm(),
            },
            Geometry::Arc { radius, sweep, .. } => radius * sweep,
            Geometry::Joint { q0, q1, weights } => weighted_distance(q0, q1, weights),
        }
    }

    /// The point at path parameter `s` (clamped to the path).
    pub(crate) fn at(&self, s: f64) -> Point {
        let len = self.length();
        let f = if len > 0.0 && s.is_finite() { (s / len).clamp(0.0, 1.0) } else { 1.0 };
        let point = |p: Vector3<f64>, ori: &OriLerp| match ori.mode {
            OriMode::Wrist { from, to } => Point::Wrist(p, super::wrist::wrist_at(from, to, f)),
            _ => Point::Tcp(p, ori.at(f)),
        };
        match self {
            Geometry::Line { p0, p1, ori } => point(p0.lerp(p1, f), ori),
            Geometry::Arc { center, radius, e1, e2, sweep, ori, drift } => {
                let phi = f * sweep;
                point(center + *radius * (phi.cos() * e1 + phi.sin() * e2) - f * drift, ori)
            }
            Geometry::Joint { q0, q1, .. } => Point::Joints(std::array::from_fn(|j| q0[j] + f * (q1[j] - q0[j]))),
        }
    }

    /// For a circle: its unit normal (the turning direction) and its sweep, radians.
    pub(crate) fn arc_turn(&self) -> Option<(nalgebra::Unit<Vector3<f64>>, f64)> {
        match self {
            Geometry::Arc { e1, e2, sweep, .. } => Some((nalgebra::Unit::new_normalize(e1.cross(e2)), *sweep)),
            _ => None,
        }
    }

    /// The fraction of a circle at which it passes `point` (a point on it).
    pub(crate) fn arc_fraction(&self, point: &Vector3<f64>) -> Option<f64> {
        let Geometry::Arc { center, e1, e2, sweep, .. } = self else { return None };
        let rel = point - center;
        let angle = rel.dot(e2).atan2(rel.dot(e1)).rem_euclid(std::f64::consts::TAU);
        (*sweep > 0.0).then(|| (angle / sweep).clamp(0.0, 1.0))
    }

    /// Sets a circle's drift (see `Geometry::Arc`).
    pub(crate) fn set_drift(&mut self, by: Vector3<f64>) {
        if let Geometry::Arc { drift, .. } = self {
            *drift = by;
        }
    }

    /// Sets the orientation interpolation (a circle's, by CirPathMode).
    pub(crate) fn set_ori(&mut self, new: OriLerp) {
        if let Geometry::Line { ori, .. } | Geometry::Arc { ori, .. } = self {
            *ori = new;
        }
    }

    /// Whether the wrist axes are interpolated in joint space (SingArea\Wrist).
    pub(crate) fn wrist_interpolated(&self) -> bool {
        matches!(self.ori(), Some(OriLerp { mode: OriMode::Wrist { .. }, .. }))
    }

    /// The orientation interpolation, for Cartesian paths.
    pub(crate) fn ori(&self) -> Option<&OriLerp> {
        match self {
            Geometry::Line { ori, .. } | Geometry::Arc { ori, .. } => Some(ori),
            Geometry::Joint { .. } => None,
        }
    }
}

/// Distance between joint vectors in the joint metric.
pub(crate) fn weighted_distance(a: &Joints, b: &Joints, weights: &[f64; 6]) -> f64 {
    (0..6).map(|j| ((b[j] - a[j]) * weights[j]).powi(2)).sum::<f64>().sqrt()
}

/// Points along the curve used to measure a corner's arc length.
const BEZIER_STEPS: usize = 32;

/// A quadratic Bézier `(1-u)²·a + 2u(1-u)·p + u²·b` in `D` dimensions, with an
/// arc-length table (each axis scaled by `weights`).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Bezier<const D: usize> {
    pub(crate) a: [f64; D],
    pub(crate) p: [f64; D],
    pub(crate) b: [f64; D],
    weights: [f64; D],
    table: [f64; BEZIER_STEPS + 1],
}

impl<const D: usize> Bezier<D> {
    pub(crate) fn new(a: [f64; D], p: [f64; D], b: [f64; D], weights: [f64; D]) -> Bezier<D> {
        let mut curve = Bezier { a, p, b, weights, table: [0.0; BEZIER_STEPS + 1] };
        // Simpson's rule on the speed |B'(u)| per step: exact enough that the
        // table's error is far below a micrometre for corners of any size.
        let h = 1.0 / BEZIER_STEPS as f64;
        for i in 1..=BEZIER_STEPS {
            let u0 = (i - 1) as f64 * h;
            let f = |u: f64| curve.speed(u);
            let step = h / 6.0 * (f(u0) + 4.0 * f(u0 + h / 2.0) + f(u0 + h));
            curve.table[i] = curve.table[i - 1] + step;
        }
        curve
    }

    /// Arc length from the start to curve parameter `u`.
    pub(crate) fn length_to(&self, u: f64) -> f64 {
        let x = if u.is_finite() { u.clamp(0.0, 1.0) * BEZIER_STEPS as f64 } else { 0.0 };
        let i = (x.floor() as usize).min(BEZIER_STEPS - 1);
        self.table[i] + (x - i as f64) * (self.table[i + 1] - self.table[i])
    }

    /// |dB/du| in the curve's metric.
    pub(crate) fn speed(&self, u: f64) -> f64 {
        let d = |k: usize| 2.0 * ((1.0 - u) * (self.p[k] - self.a[k]) + u * (self.b[k] - self.p[k])) * self.weights[k];
        (0..D).map(|k| d(k).powi(2)).sum::<f64>().sqrt()
    }

    /// The per-axis scale of the metric the curve is measured in.
    pub(crate) fn weights(&self) -> [f64; D] {
        self.weights
    }

    /// The point at curve parameter `u` in 0..=1.
    pub(crate) fn point(&self, u: f64) -> [f64; D] {
        let u = u.clamp(0.0, 1.0);
        let (c0, c1, c2) = ((1.0 - u) * (1.0 - u), 2.0 * u * (1.0 - u), u * u);
        std::array::from_fn(|k| c0 * self.a[k] + c1 * self.p[k] + c2 * self.b[k])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ori() -> OriLerp {
        OriLerp::fixed(UnitQuaternion::identity(), UnitQuaternion::identity())
    }

    #[test]
    fn quarter_circle_is_pi_r_over_2() {
        let r = 100.0;
        let h = r * std::f64::consts::FRAC_1_SQRT_2;
        let arc = Geometry::arc(Vector3::new(r, 0.0, 0.0), Vector3::new(h, h, 0.0), Vector3::new(0.0, r, 0.0), ori())
            .unwrap();
        assert!((arc.length() - std::f64::consts::PI * r / 2.0).abs() < 1e-9);
        let Point::Tcp(mid, _) = arc.at(arc.length() / 2.0) else { unreachable!("arcs are Cartesian") };
        assert!((mid - Vector3::new(h, h, 0.0)).norm() < 1e-9);
    }

    #[test]
    fn three_quarter_circle_goes_the_long_way() {
        // Via (0, -r): the arc from (r, 0) to (0, r) turns clockwise through 270°.
        let r = 50.0;
        let arc =
            Geometry::arc(Vector3::new(r, 0.0, 0.0), Vector3::new(0.0, -r, 0.0), Vector3::new(0.0, r, 0.0), ori())
                .unwrap();
        assert!((arc.length() - 1.5 * std::f64::consts::PI * r).abs() < 1e-9);
    }

    /// A quarter circle from (r, 0, 0) to (0, r, 0) about +z (sweep 90°).
    fn quarter(from: UnitQuaternion<f64>, to: UnitQuaternion<f64>) -> Geometry {
        let r = 100.0;
        let h = r * std::f64::consts::FRAC_1_SQRT_2;
        let fixed = OriLerp::fixed(from, to);
        let mut arc =
            Geometry::arc(Vector3::new(r, 0.0, 0.0), Vector3::new(h, h, 0.0), Vector3::new(0.0, r, 0.0), fixed)
                .unwrap();
        let (normal, sweep) = arc.arc_turn().unwrap();
        arc.set_ori(OriLerp { mode: OriMode::PathFrame { normal, sweep, turns: 0.0 }, ..fixed });
        arc
    }

    fn ori_at(geom: &Geometry, fraction: f64) -> UnitQuaternion<f64> {
        geom.ori().unwrap().at(fraction)
    }

    #[test]
    fn path_frame_keeps_a_tool_that_turns_with_the_path_turning_with_it() {
        let deg = f64::to_radians;
        let tilt = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), deg(30.0));
        let turned = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), deg(90.0)) * tilt;
        let arc = quarter(tilt, turned);
        // Half way round, the tool has turned half of the path's 90° about z.
        let half = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), deg(45.0)) * tilt;
        assert!(ori_at(&arc, 0.5).angle_to(&half) < 1e-12);
        assert!(ori_at(&arc, 1.0).angle_to(&turned) < 1e-12);
    }

    #[test]
    fn path_frame_interpolates_relative_to_the_tangent() {
        // From no rotation to Rx(90°) on a quarter circle about z. Relative to the
        // path frame the end is Rz(-90°)·Rx(90°) = [[0,0,-1],[-1,0,0],[0,1,0]]: trace
        // 0, so 120° about (1,-1,-1)/√3. Half way: the path frame turned 45°, the
        // relative rotation 60° about the same axis.
        let deg = f64::to_radians;
        let arc = quarter(UnitQuaternion::identity(), UnitQuaternion::from_axis_angle(&Vector3::x_axis(), deg(90.0)));
        let axis = nalgebra::Unit::new_normalize(Vector3::new(1.0, -1.0, -1.0));
        let expected = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), deg(45.0))
            * UnitQuaternion::from_axis_angle(&axis, deg(60.0));
        assert!(ori_at(&arc, 0.5).angle_to(&expected) < 1e-12);
        // \ObjectFrame would be half of Rx(90°): a different orientation.
        let object = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), deg(45.0));
        assert!(ori_at(&arc, 0.5).angle_to(&object) > deg(10.0));
    }

    #[test]
    fn path_frame_on_a_long_circle_goes_the_way_the_circle_point_shows() {
        // A 270° circle about z with the tool pointing down all the way (start, circle
        // point and end alike). Relative to the path the end is Rz(−270°) = Rz(90°) from
        // the start: the short way turns +90° while the path turns +270°, a whole turn of
        // the tool. The circle point (pointing down, like the others) picks −1 added
        // turn: the tool keeps its orientation everywhere.
        let deg = f64::to_radians;
        let down = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), deg(180.0));
        let normal = Vector3::z_axis();
        let fixed = OriLerp::fixed(down, down);
        let ori = OriLerp::path_frame(fixed, normal, deg(270.0), (&down, 0.5));
        for k in 0..=8 {
            let f = k as f64 / 8.0;
            assert!(ori.at(f).angle_to(&down) < 1e-9, "at {f}: {}°", ori.at(f).angle_to(&down).to_degrees());
        }
        // A tool that turns with the path (the circle point turned 135°, half way)
        // keeps no added turn: 135° about z half way, the path's own turn.
        let turning = UnitQuaternion::from_axis_angle(&normal, deg(270.0)) * down;
        let via = UnitQuaternion::from_axis_angle(&normal, deg(135.0)) * down;
        let ori = OriLerp::path_frame(OriLerp::fixed(down, turning), normal, deg(270.0), (&via, 0.5));
        assert!(ori.at(0.5).angle_to(&via) < 1e-9);
        assert!(matches!(ori.mode, OriMode::PathFrame { turns, .. } if turns == 0.0));
    }

    #[test]
    fn cir_point_ori_passes_through_the_circle_points_orientation() {
        let deg = f64::to_radians;
        let r = 100.0;
        let fixed = OriLerp::fixed(UnitQuaternion::identity(), UnitQuaternion::identity());
        // A half circle through its top: the circle point is half way.
        let mut arc =
            Geometry::arc(Vector3::new(r, 0.0, 0.0), Vector3::new(0.0, r, 0.0), Vector3::new(-r, 0.0, 0.0), fixed)
                .unwrap();
        let at = arc.arc_fraction(&Vector3::new(0.0, r, 0.0)).unwrap();
        assert!((at - 0.5).abs() < 1e-12);
        let via = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), deg(40.0));
        arc.set_ori(OriLerp { mode: OriMode::ViaPoint { via, at }, ..fixed });
        assert!(ori_at(&arc, 0.5).angle_to(&via) < 1e-12);
        let quarter_way = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), deg(20.0));
        assert!(ori_at(&arc, 0.25).angle_to(&quarter_way) < 1e-12);
        // Up 40° and back down: 80° of reorientation in all.
        assert!((arc.ori().unwrap().angle() - 80.0).abs() < 1e-9);
    }

    #[test]
    fn degenerate_circles_are_errors() {
        let p = |x: f64| Vector3::new(x, 0.0, 0.0);
        assert_eq!(Geometry::arc(p(0.0), p(1.0), p(2.0), ori()), Err(MotionError::DegenerateCircle));
        assert_eq!(Geometry::arc(p(0.0), p(0.0), p(2.0), ori()), Err(MotionError::DegenerateCircle));
        let nan = Vector3::new(f64::NAN, 0.0, 0.0);
        assert_eq!(Geometry::arc(p(0.0), nan, p(2.0), ori()), Err(MotionError::DegenerateCircle));
    }

    #[test]
    fn right_angle_parabola_length() {
        // Legs d = 10 at 90°: length 2√2·d·(√2/4 + ln(1 + √2)/8), worked by hand
        // from ∫|B'(u)|du = 16.2323 mm.
        let curve = Bezier::new([0.0, -10.0], [0.0, 0.0], [10.0, 0.0], [1.0, 1.0]);
        assert!((curve.length_to(1.0) - 16.2323).abs() < 1e-3);
        assert!((curve.length_to(0.5) - 16.2323 / 2.0).abs() < 1e-3);
        assert_eq!(curve.length_to(f64::NAN), 0.0);
    }
}
