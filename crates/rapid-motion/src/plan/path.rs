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
/// `to` over the move's fraction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct OriLerp {
    pub(crate) from: UnitQuaternion<f64>,
    pub(crate) to: UnitQuaternion<f64>,
}

impl OriLerp {
    pub(crate) fn at(&self, fraction: f64) -> UnitQuaternion<f64> {
        // try_slerp returns None only for opposite quaternions at half way; the
        // start orientation is then as good an answer as any.
        self.from.try_slerp(&self.to, fraction.clamp(0.0, 1.0), 1e-12).unwrap_or(self.from)
    }

    /// The reorientation angle, degrees.
    pub(crate) fn angle(&self) -> f64 {
        self.from.angle_to(&self.to).to_degrees()
    }
}

/// One move's path.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Geometry {
    /// A straight TCP line (MoveL), orientation slerped along it.
    Line { p0: Vector3<f64>, p1: Vector3<f64>, ori: OriLerp },
    /// A circle arc (MoveC) from `center + radius·e1`, turning towards `e2`
    /// through `sweep` radians.
    Arc { center: Vector3<f64>, radius: f64, e1: Vector3<f64>, e2: Vector3<f64>, sweep: f64, ori: OriLerp },
    /// A straight line in joint space (MoveJ, MoveAbsJ); `weights` are the
    /// inverse axis speeds that define the joint metric.
    Joint { q0: Joints, q1: Joints, weights: [f64; 6] },
}

/// A point on a path: a TCP pose in the base frame or joint values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Point {
    Tcp(Vector3<f64>, UnitQuaternion<f64>),
    Joints(Joints),
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
        Ok(Geometry::Arc { center, radius, e1, e2, sweep, ori })
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
        match self {
            Geometry::Line { p0, p1, ori } => Point::Tcp(p0.lerp(p1, f), ori.at(f)),
            Geometry::Arc { center, radius, e1, e2, sweep, ori } => {
                let phi = f * sweep;
                Point::Tcp(center + *radius * (phi.cos() * e1 + phi.sin() * e2), ori.at(f))
            }
            Geometry::Joint { q0, q1, .. } => Point::Joints(std::array::from_fn(|j| q0[j] + f * (q1[j] - q0[j]))),
        }
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
        OriLerp { from: UnitQuaternion::identity(), to: UnitQuaternion::identity() }
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
