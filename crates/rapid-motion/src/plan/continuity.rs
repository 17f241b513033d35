//! A Cartesian path's joints must change continuously. Solved sample by sample near
//! the one before, the inverse kinematics can land on another branch where the
//! continuous one leaves an axis's range: the robot would jump. Between samples whose
//! axes change much, the path is bisected until every step is small (passing near a
//! singularity, the wrist axes turn fast but continuously) or the step is a jump, which
//! the controller refuses: the axis out of range (50028), else close to a singularity
//! (50026). From or to the wrist singularity itself axes 4 and 6 may turn as they
//! need: the pose fixes only their sum there.

use crate::{Joints, Kinematics, MotionError};

/// Solves the path at a path parameter, near a seed.
pub(crate) type Solve<'a> = dyn Fn(f64, &Joints) -> Result<Joints, MotionError> + 'a;

/// Neighbouring samples whose axes differ by at most this (°) need no closer look.
const STEP_DEG: f64 = 10.0;
/// Samples this close on the path (mm or °) that still differ by more are a jump.
const FINEST: f64 = 1e-6;
/// Axis 5 this close to 0 (°) is at the wrist singularity.
const WRIST_SINGULAR_DEG: f64 = 1e-3;
/// At most this many samples are added to one move; beyond, the steps are taken as
/// they are (a bound on the work for a pathological path).
pub(crate) const MAX_ADDED: usize = 512;

/// The samples between `a` and the path parameter `s_b`, ending with `s_b` solved
/// continuously from `a`, appended to `out`; `q_b` is `s_b` solved from `a`'s joints.
/// Returns the joints at `s_b`. `path` is the arm and how the path is solved at a path
/// parameter from a seed.
pub(crate) fn bridge<K: Kinematics + ?Sized>(
    path: (&K, &Solve<'_>),
    a: (f64, Joints),
    (s_b, q_b): (f64, Joints),
    out: &mut Vec<(f64, Joints)>,
    budget: &mut usize,
) -> Result<Joints, MotionError> {
    let (kin, solve) = path;
    let (s_a, q_a) = a;
    if largest_step(&q_a, &q_b) <= STEP_DEG || wrist_turn(&q_a, &q_b) || *budget == 0 {
        out.push((s_b, q_b));
        return Ok(q_b);
    }
    if s_b - s_a <= FINEST {
        return Err(jump(kin, &q_a));
    }
    *budget -= 1;
    let s_mid = (s_a + s_b) / 2.0;
    let q_mid = solve(s_mid, &q_a)?;
    let q_mid = bridge(path, a, (s_mid, q_mid), out, budget)?;
    // The far end again, from the middle: the continuous branch if there is one.
    let q_b = solve(s_b, &q_mid)?;
    bridge(path, (s_mid, q_mid), (s_b, q_b), out, budget)
}

/// At a wrist singularity (axis 5 at 0) the pose fixes only the sum of axes 4 and 6:
/// a step from or to there that turns them is no jump (leaving the calibration
/// position, say); it is taken as the step it is, as before there was a closer look.
fn wrist_turn(a: &Joints, b: &Joints) -> bool {
    let singular = a[4].abs().min(b[4].abs()) < WRIST_SINGULAR_DEG;
    singular && [0, 1, 2, 4].iter().all(|&j| (a[j] - b[j]).abs() <= STEP_DEG)
}

/// The largest change of one axis between two joint sets (°).
fn largest_step(a: &Joints, b: &Joints) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
}

/// Why the joints cannot go on continuously from `q`: the axis nearest its range's
/// end (the continuous branch leaves the range there), or a singularity.
fn jump<K: Kinematics + ?Sized>(kin: &K, q: &Joints) -> MotionError {
    let limits = kin.limits();
    let margin = |j: usize| (q[j] - limits[j].0).min(limits[j].1 - q[j]);
    match (0..6).filter(|&j| margin(j) <= STEP_DEG).min_by(|&i, &j| margin(i).total_cmp(&margin(j))) {
        Some(j) => MotionError::JointLimit { axis: j + 1 },
        None => MotionError::Singularity,
    }
}
