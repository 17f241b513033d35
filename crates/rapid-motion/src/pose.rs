//! Poses and joint values in RAPID units (mm, degrees, scalar-first quaternions),
//! on nalgebra's isometries.

use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};

/// Six axis angles in degrees, axis 1 first.
pub type Joints = [f64; 6];

/// A frame: translation in mm and a rotation.
pub type Pose = Isometry3<f64>;

/// The pose of RAPID `[[x, y, z], [q1, q2, q3, q4]]` (the quaternion is normalised,
/// as RAPID requires of an orient used in motion).
pub fn pose(trans: [f64; 3], orient: [f64; 4]) -> Pose {
    let [q1, q2, q3, q4] = orient;
    let rotation = UnitQuaternion::from_quaternion(Quaternion::new(q1, q2, q3, q4));
    Isometry3::from_parts(Translation3::new(trans[0], trans[1], trans[2]), rotation)
}

/// The pose of `[[x, y, z], [q1, q2, q3, q4]]`, or `None` when a component is not a
/// number or the quaternion is (nearly) zero and so names no rotation; the VM reports
/// that as the controller's unnormalised-orientation error.
pub fn checked_pose(trans: [f64; 3], orient: [f64; 4]) -> Option<Pose> {
    let finite = trans.iter().chain(&orient).all(|v| v.is_finite());
    let norm = orient.iter().map(|q| q * q).sum::<f64>().sqrt();
    (finite && norm > 1e-9).then(|| pose(trans, orient))
}

/// The translation of a pose, mm.
pub fn trans(pose: &Pose) -> [f64; 3] {
    let v: Vector3<f64> = pose.translation.vector;
    [v.x, v.y, v.z]
}

/// The rotation of a pose as RAPID's `[q1, q2, q3, q4]`, scalar first, with q1 ≥ 0
/// (the sign the controller shows; both signs are the same rotation).
pub fn orient(pose: &Pose) -> [f64; 4] {
    // Below this a component is rounding noise (a half turn's q1 is 0 up to ~1e-17).
    const NOISE: f64 = 1e-12;
    let q = pose.rotation.quaternion();
    // q1 ≥ 0; for a half turn (q1 = 0) the first non-zero of q2…q4 is positive, so one
    // orientation reads back one way whatever path led to it.
    // uncertain: the controller's sign for half turns (the usual matrix-to-quaternion
    // conversion makes the largest component positive; for a half turn about one
    // axis, as a tool pointing down, the two agree).
    let lead = [q.w, q.i, q.j, q.k].into_iter().find(|c| c.abs() > NOISE).unwrap_or(q.w);
    let sign = if lead < 0.0 { -1.0 } else { 1.0 };
    [sign * q.w, sign * q.i, sign * q.j, sign * q.k]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_keeps_rapid_order() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let p = pose([374.0, 0.0, 630.0], [h, 0.0, h, 0.0]);
        let o = orient(&p);
        assert!((o[0] - 0.5f64.sqrt()).abs() < 1e-6 && (o[2] - 0.5f64.sqrt()).abs() < 1e-6);
        assert_eq!(trans(&p), [374.0, 0.0, 630.0]);
    }

    #[test]
    fn a_half_turn_reads_back_one_way() {
        // 180° about y, whichever sign the quaternion arrived with (q1 a rounding
        // error either side of 0): [0, 0, 1, 0].
        for (w, y) in [(1e-17, 1.0), (-1e-17, 1.0), (1e-17, -1.0), (-1e-17, -1.0)] {
            let p = Isometry3::from_parts(
                Translation3::identity(),
                UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(w, 0.0, y, 0.0)),
            );
            assert_eq!(orient(&p).map(|c| if c.abs() < 1e-12 { 0.0 } else { c }), [0.0, 0.0, 1.0, 0.0]);
        }
    }

    #[test]
    fn checked_pose_refuses_what_names_no_rotation() {
        assert!(checked_pose([0.0; 3], [0.0; 4]).is_none());
        assert!(checked_pose([f64::NAN, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]).is_none());
        assert!(checked_pose([0.0; 3], [f64::INFINITY, 0.0, 0.0, 0.0]).is_none());
        // Not normalised is normalised, as NOrient would.
        let p = checked_pose([1.0, 2.0, 3.0], [2.0, 0.0, 0.0, 0.0]).unwrap();
        assert_eq!(orient(&p), [1.0, 0.0, 0.0, 0.0]);
    }
}
