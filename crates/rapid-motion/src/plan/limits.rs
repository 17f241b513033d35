//! Nominal accelerations and the stop-point settle time: the one place the
//! timing model's unpublished constants live, so they can be calibrated against
//! RobotStudio cycle times without touching the planner.

/// Acceleration limits at AccSet 100 %, and the settle time of a stop point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccelLimits {
    /// Path acceleration of the TCP, mm/s².
    pub tcp: f64,
    /// Reorientation acceleration, °/s².
    pub ori: f64,
    /// Per-axis acceleration, °/s².
    pub joint: [f64; 6],
    /// Time a stop point (`fine`) adds after the robot has stopped, s.
    pub settle: f64,
}

// uncertain: ABB publishes no accelerations (its controller derives them from a
// dynamic model with the payload). The IRB 120 data sheet gives a maximum TCP
// acceleration of 28 m/s² and about 0.07 s to reach 1 m/s, as we remember it;
// we take a third of the peak as a conservative path value.
const TCP_ACCEL: f64 = 10_000.0;
// uncertain: reorientation acceleration, chosen so a 500 °/s reorientation
// ramps up in 0.25 s.
const ORI_ACCEL: f64 = 2_000.0;
// uncertain: every axis reaches its maximum speed in this time.
const AXIS_RAMP_TIME: f64 = 0.15;
// uncertain: how long the controller waits in position at a `fine` point
// (stoppointdata inpos/stoptime are not modelled).
const SETTLE_TIME: f64 = 0.05;
// uncertain: robots whose axis 1 is slower than this are heavy arms, whose path
// acceleration we scale down with the axis speed.
const LIGHT_AXIS1_SPEED: f64 = 250.0;

impl AccelLimits {
    /// Nominal limits for a robot with these maximum axis speeds (°/s): axes
    /// reach full speed in a fixed ramp time, and the path acceleration shrinks
    /// with axis 1's speed for heavy arms (slower axes, larger inertia).
    pub fn nominal(max_speeds: &[f64; 6]) -> AccelLimits {
        let clean = |v: f64| if v.is_finite() && v > 0.0 { v } else { 1.0 };
        let joint = max_speeds.map(|v| clean(v) / AXIS_RAMP_TIME);
        let heavy = (clean(max_speeds[0]) / LIGHT_AXIS1_SPEED).min(1.0);
        AccelLimits { tcp: TCP_ACCEL * heavy, ori: ORI_ACCEL * heavy, joint, settle: SETTLE_TIME }
    }

    /// The limits scaled by AccSet's factor (0.2 ..= 1).
    pub fn scaled(&self, factor: f64) -> AccelLimits {
        AccelLimits {
            tcp: self.tcp * factor,
            ori: self.ori * factor,
            joint: self.joint.map(|a| a * factor),
            settle: self.settle,
        }
    }

    /// The same limits with every value made finite and positive, so the planner
    /// can divide by them.
    pub(crate) fn sanitized(&self) -> AccelLimits {
        let clean = |a: f64| if a.is_finite() && a > 0.0 { a } else { 1.0 };
        AccelLimits {
            tcp: clean(self.tcp),
            ori: clean(self.ori),
            joint: self.joint.map(clean),
            settle: if self.settle.is_finite() { self.settle.max(0.0) } else { 0.0 },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nominal_follows_axis_speeds() {
        let light = AccelLimits::nominal(&[250.0, 250.0, 250.0, 320.0, 320.0, 420.0]);
        assert_eq!(light.tcp, TCP_ACCEL);
        assert!((light.joint[0] - 250.0 / AXIS_RAMP_TIME).abs() < 1e-9);
        let heavy = AccelLimits::nominal(&[100.0, 90.0, 90.0, 170.0, 140.0, 190.0]);
        assert!((heavy.tcp - TCP_ACCEL * 0.4).abs() < 1e-9);
        let broken = AccelLimits::nominal(&[f64::NAN, -1.0, 0.0, 1.0, 1.0, 1.0]);
        assert!(broken.tcp > 0.0 && broken.joint.iter().all(|a| a.is_finite() && *a > 0.0));
    }
}
