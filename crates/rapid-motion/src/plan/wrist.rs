//! SingArea\Wrist (§2.2.2, "SingArea\Wrist"): near singular points a linear or
//! circular move may interpolate the wrist axes axis by axis while the TCP keeps its
//! line or circle; the tool's orientation then differs somewhat from the programmed
//! one. Here the wrist axes (4, 5, 6) go in a straight line in joint space from the
//! move's start to the end's solution, and axes 1–3 are solved at each point of the
//! path so the TCP is on it.
// uncertain: the manual says the wrist is interpolated axis by axis; a straight line
// in joint space over the path's fraction is our reading.

use nalgebra::{Matrix3, Vector3};

use crate::{Joints, Kinematics, MotionError, Pose};

/// The TCP closer than this (mm, a nanometre) to the point is on it.
const TOLERANCE_MM: f64 = 1e-6;
/// Newton steps before the point counts as out of reach.
const MAX_STEPS: usize = 40;
/// The largest change of an arm axis in one Newton step (°): far steps keep to the
/// seed's branch.
const MAX_STEP_DEG: f64 = 10.0;
/// The difference step of the Jacobian (°).
const H_DEG: f64 = 1e-6;
/// Steps between fresh Jacobians.
const REFRESH: usize = 4;

/// The axes that put the TCP (`tool` on the flange) at `p` with the wrist axes at
/// `wrist` (axes 4, 5, 6), axes 1–3 found from `seed`'s by Newton's method.
/// `OutOfReach` when no such arm position is near, `JointLimit` when it leaves a range.
pub(crate) fn arm_for<K: Kinematics + ?Sized>(
    kin: &K,
    tool: &Pose,
    p: &Vector3<f64>,
    wrist: [f64; 3],
    seed: &Joints,
) -> Result<Joints, MotionError> {
    let mut q = [seed[0], seed[1], seed[2], wrist[0], wrist[1], wrist[2]];
    let tcp = |q: &Joints| (kin.forward(q) * tool).translation.vector;
    let mut here = tcp(&q);
    let mut solver = None;
    for step in 0..MAX_STEPS {
        let error = p - here;
        if !error.iter().all(|e| e.is_finite()) {
            break;
        }
        if error.norm() < TOLERANCE_MM {
            return super::segment::check_limits(&kin.limits(), &q).map(|()| q);
        }
        // The Jacobian is taken afresh every few steps (a chord method between): the
        // seed is near, so it changes little.
        if step % REFRESH == 0 || solver.is_none() {
            solver = Some(jacobian(&tcp, &q, &here).lu());
        }
        let Some(delta) = solver.as_ref().and_then(|lu| lu.solve(&error)) else { break };
        let largest = delta.amax();
        let scale = if largest > MAX_STEP_DEG { MAX_STEP_DEG / largest } else { 1.0 };
        for j in 0..3 {
            q[j] += delta[j] * scale;
        }
        here = tcp(&q);
    }
    Err(MotionError::OutOfReach)
}

/// The TCP's change per degree of axes 1–3 at `q` (the TCP `here`), by differences.
fn jacobian(tcp: &impl Fn(&Joints) -> Vector3<f64>, q: &Joints, here: &Vector3<f64>) -> Matrix3<f64> {
    let mut jacobian = Matrix3::zeros();
    for j in 0..3 {
        let mut moved = *q;
        moved[j] += H_DEG;
        jacobian.set_column(j, &((tcp(&moved) - here) / H_DEG));
    }
    jacobian
}

/// The wrist axes a fraction `f` of the way from `from` to `to`.
pub(crate) fn wrist_at(from: [f64; 3], to: [f64; 3], f: f64) -> [f64; 3] {
    std::array::from_fn(|k| from[k] + f * (to[k] - from[k]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::default_model;

    #[test]
    fn the_arm_is_found_for_the_wrist_and_the_point() {
        // Joints known, their TCP computed: from a seed 5° away on each arm axis the
        // solver returns the same arm.
        let kin = default_model().kinematics();
        let tool = Pose::translation(0.0, 0.0, 100.0);
        let q = [20.0, 15.0, -10.0, 30.0, 40.0, -50.0];
        let p = (kin.forward(&q) * tool).translation.vector;
        let seed = [25.0, 10.0, -5.0, 0.0, 0.0, 0.0];
        let found = arm_for(&kin, &tool, &p, [30.0, 40.0, -50.0], &seed).expect("a solution");
        assert!(found.iter().zip(q).all(|(a, b)| (a - b).abs() < 1e-6), "{found:?}");
    }

    #[test]
    fn a_point_out_of_reach_is_an_error() {
        let kin = default_model().kinematics();
        let far = Vector3::new(2000.0, 0.0, 300.0);
        let got = arm_for(&kin, &Pose::identity(), &far, [0.0, 30.0, 0.0], &[0.0; 6]);
        assert_eq!(got, Err(MotionError::OutOfReach));
    }
}
