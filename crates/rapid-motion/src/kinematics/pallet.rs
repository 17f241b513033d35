//! The 4-axis palletizers (IRB 260, 460, 660, 760): axis 1 turns the arm, axes 2 and 3
//! drive the lower and the upper arm through parallelograms, and axis 6 turns the
//! flange, which the linkage keeps level, tool0's z axis pointing straight down.
//!
//! Joint convention (ABB's as RoboDK models it, see `robots.rs` for the source): all
//! axes 0 has the lower arm upright and the upper arm level; axis 2 positive leans the
//! lower arm forward; axis 3 is the upper arm's own angle below the horizontal (the
//! parallelogram makes it independent of axis 2), so the upper arm does not follow the
//! lower arm as on a 6-axis arm. Axes 4 and 5 do not exist: they stay at 0. At all axes
//! 0 tool0 is turned 180° about y (x backwards, z down), as a 6-axis arm's with axis 5 at
//! 90°. Axis 6 turns the flange about its own z, so about the base's −z: the flange's
//! heading about the base z is q1 − q6.

use std::f64::consts::PI;

use nalgebra::{Translation3, UnitQuaternion, Vector3};

use crate::kinematics::Branches;
use crate::{Joints, Pose};

/// A palletizer's link lengths in mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PalletParams {
    /// Height of axis 2 above the base.
    pub d1: f64,
    /// Axis 2's offset forward of axis 1.
    pub a1: f64,
    /// The lower arm (axis 2 to axis 3).
    pub l2: f64,
    /// The upper arm (axis 3 to the wrist).
    pub l3: f64,
    /// The flange's offset forward of the wrist.
    pub a4: f64,
    /// The flange's drop below the wrist.
    pub d5: f64,
}

/// How far (radians) tool0's z axis may lean off straight down and still be reachable:
/// the linkage holds the flange level, so any other orientation is out of reach. The
/// band takes a robtarget's single-precision rounding.
// uncertain: how the controller treats a robtarget whose orientation a palletizer
// cannot take (refused, or projected onto the level orientations) is not public; we
// refuse it as out of reach.
const LEVEL_TOLERANCE: f64 = 1e-4;

/// The flange pose of the joints.
pub(super) fn forward(p: &PalletParams, joints: &Joints) -> Pose {
    let [q1, q2, q3, _, _, q6] = joints.map(f64::to_radians);
    let reach = p.a1 + p.l2 * q2.sin() + p.l3 * q3.cos() + p.a4;
    let height = p.d1 + p.l2 * q2.cos() - p.l3 * q3.sin() - p.d5;
    let (s1, c1) = q1.sin_cos();
    let position = Vector3::new(reach * c1, reach * s1, height);
    let rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), q1 - q6)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), PI);
    Pose::from_parts(Translation3::from(position), rotation)
}

/// The solutions of a flange pose, indexed as a 6-axis arm's by cfx: bit 2 set with
/// the flange behind axis 1, bit 1 with the upper arm on the far side of the lower
/// arm's line; axis 5 is always 0 (bit 0 never set). Angles in (−180°, 180°], limits not
/// applied. On axis 1 (the flange straight above it) axis 1 keeps the seed's value.
pub(super) fn branches(p: &PalletParams, flange: &Pose, seed: Option<&Joints>) -> Branches {
    let mut res: Branches = [None; 8];
    let position = flange.translation.vector;
    let down = flange.rotation * Vector3::z();
    if !position.iter().all(|v| v.is_finite()) || !down.iter().all(|v| v.is_finite()) {
        return res;
    }
    if down.z > -(LEVEL_TOLERANCE.cos()) {
        return res;
    }
    // The heading of tool0's x axis, which points backwards at q1 − q6 = 0.
    let x = flange.rotation * Vector3::x();
    let heading = (-x.y).atan2(-x.x);
    let rho = position.x.hypot(position.y);
    let ahead = if rho < 1e-9 { seed.map_or(0.0, |s| s[0].to_radians()) } else { position.y.atan2(position.x) };
    for (behind, q1, reach) in [(false, ahead, rho), (true, ahead + PI, -rho)] {
        // The wrist (the upper arm's end) in the arm's plane, from axis 2.
        let dx = reach - p.a4 - p.a1;
        let dz = position.z + p.d5 - p.d1;
        for (far, q2, q3) in arm(p, dx, dz).into_iter().flatten() {
            let q6 = q1 - heading;
            let joints = [q1, q2, q3, 0.0, 0.0, q6].map(|q| principal(q).to_degrees());
            res[4 * behind as usize + 2 * far as usize] = Some(joints);
        }
    }
    res
}

/// Axes 2 and 3 putting the upper arm's end at (dx, dz) from axis 2: both ways of the
/// triangle, (upper arm beyond the lower arm's line, q2, q3), `None` out of reach.
fn arm(p: &PalletParams, dx: f64, dz: f64) -> [Option<(bool, f64, f64)>; 2] {
    let dist_sq = dx * dx + dz * dz;
    // The lower arm at angle q2 from upright: (l2 sin q2, l2 cos q2); the upper arm
    // (l3 cos q3, −l3 sin q3). Law of cosines for the angle at axis 3.
    let cos_gamma = (p.l2 * p.l2 + p.l3 * p.l3 - dist_sq) / (2.0 * p.l2 * p.l3);
    if !cos_gamma.is_finite() || cos_gamma.abs() > 1.0 + 1e-9 {
        return [None, None];
    }
    let gamma = cos_gamma.clamp(-1.0, 1.0).acos();
    // The angle at axis 2 between the target and the lower arm.
    let beta = (p.l3 * gamma.sin()).atan2(p.l2 - p.l3 * gamma.cos());
    let target = dx.atan2(dz);
    // Elbow one way: the lower arm leans back of the target line by beta.
    let solve = |sign: f64| {
        let q2 = target - sign * beta;
        let (ex, ez) = (dx - p.l2 * q2.sin(), dz - p.l2 * q2.cos());
        let q3 = (-ez).atan2(ex);
        (far_side(q2, q3), q2, q3)
    };
    [Some(solve(1.0)), Some(solve(-1.0))]
}

/// The upper arm's end beyond the lower arm's line (the elbow folded the other way):
/// `cos(q2 − q3) < 0` (radians).
fn far_side(q2: f64, q3: f64) -> bool {
    (q2 - q3).cos() < 0.0
}

/// cfx of a palletizer's joints: 4 with the flange behind axis 1, 2 with the upper arm
/// beyond the lower arm's line.
// uncertain: the manual's confdata page describes cfx for 6-axis arms; we keep its
// meaning (wrist behind axis 1, elbow on the other side) for the palletizers.
pub(crate) fn cfx(p: &PalletParams, joints: &Joints) -> i32 {
    let [_, q2, q3, ..] = joints.map(f64::to_radians);
    let reach = p.a1 + p.l2 * q2.sin() + p.l3 * q3.cos() + p.a4;
    4 * (reach < 0.0) as i32 + 2 * far_side(q2, q3) as i32
}

/// The angle in (−π, π].
fn principal(q: f64) -> f64 {
    let r = super::wrap(q, 2.0 * PI);
    if r > PI {
        r - 2.0 * PI
    } else {
        r
    }
}
