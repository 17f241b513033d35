//! The closed-form inverse of an OPW arm: axis 1 from the wrist centre, axes 2 and 3
//! from the triangle shoulder–elbow–wrist, axes 4 to 6 as Z-Y-Z angles of the wrist.
//!
//! Derived for ABB's convention directly (see `Opw::wrist_centre` for the forward
//! form it inverts), so no offsets or sign corrections are needed.

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Matrix3, Vector3};

use crate::kinematics::OpwParams;
use crate::{Joints, Pose};

/// The eight solutions of one pose indexed by cfx; `None` where that arm
/// configuration cannot reach the pose.
pub type Branches = [Option<Joints>; 8];

/// Below this, `sin q5` counts as zero and axes 4 and 6 only have a sum (or difference).
const WRIST_SINGULAR: f64 = 1e-10;
/// Below this `sin q5` (about 0.0006°) axes 4 and 6 are still found from the pose, but
/// their split is rounding noise: a pose read back at the singularity and stored in
/// RAPID's single-precision `num` (CRobT, a robtarget printed with six decimals) is off
/// the singularity by some 1e-7. With a seed, axis 4 then keeps the seed's value and
/// axis 6 the rest of their sum, as at the singularity itself; the pose moves by less
/// than 2e-5 rad (a hundredth of a millimetre at half a metre from the wrist).
// uncertain: the real controller's band is not public; it must at least hold the f32
// rounding of a robtarget (issue 20 item 6: MoveJ CRobT() from the calibration position).
pub(crate) const WRIST_NEAR_SINGULAR: f64 = 1e-5;
/// Below this distance (mm) from axis 1 the wrist centre counts as on the axis.
const SHOULDER_SINGULAR: f64 = 1e-9;
/// How far past a stretched arm (in the cosine of the elbow angle) still counts as
/// reachable; rounding in a pose computed by forward kinematics stays well below it.
const REACH_SLACK: f64 = 1e-9;

pub(super) fn branches(p: &OpwParams, flange: &Pose, seed: Option<&Joints>) -> Branches {
    let mut res: Branches = [None; 8];
    let rotation: Matrix3<f64> = *flange.rotation.to_rotation_matrix().matrix();
    let position = flange.translation.vector;
    if !rotation.iter().all(|v| v.is_finite()) || !position.iter().all(|v| v.is_finite()) {
        return res;
    }
    let wrist = position - p.c4 * rotation.column(2);
    let seed_rad = seed.map(|s| s.map(f64::to_radians));
    let Some(shoulders) = axis1(p, &wrist, seed_rad.as_ref()) else { return res };
    for (behind_axis1, q1, x1) in shoulders {
        let dx = x1 - p.a1;
        let dz = wrist.z - p.c1;
        let Some(elbows) = elbow(p, dx, dz) else { continue };
        for (behind_arm, q2, q3) in elbows {
            let wrist_rot = wrist_rotation(q1, q2 + q3, &rotation);
            for (negative_q5, q456) in wrist_angles(&wrist_rot, seed_rad.as_ref()) {
                let idx = 4 * behind_axis1 as usize + 2 * behind_arm as usize + negative_q5 as usize;
                let joints = [q1, q2, q3, q456[0], q456[1], q456[2]].map(|q| principal(q).to_degrees());
                res[idx] = Some(joints);
            }
        }
    }
    res
}

/// The solution nearest to `seed` (degrees), computed on the seed's own branch only,
/// when that is provably the answer the search over all eight branches gives: its
/// largest axis move is smaller than a lower bound of every other branch's (the other
/// shoulder's axis 1, the other elbow's axes 2–3, the other wrist flip's axes 4–6,
/// each taken modulo a turn). `None` near a singularity, when a bound is too close, or
/// when the branch leaves the limits: the caller then searches all branches. Following
/// a path with a close seed, this is one branch's trigonometry instead of eight.
pub(super) fn seeded(p: &OpwParams, flange: &Pose, seed: &Joints, limits: &[(f64, f64); 6]) -> Option<Joints> {
    let rotation: Matrix3<f64> = *flange.rotation.to_rotation_matrix().matrix();
    let position = flange.translation.vector;
    let wrist = position - p.c4 * rotation.column(2);
    if !wrist.iter().all(|v| v.is_finite()) || wrist.x.hypot(wrist.y) < SHOULDER_SINGULAR {
        return None;
    }
    let seed_rad = seed.map(f64::to_radians);
    let [front, behind] = axis1(p, &wrist, None)?;
    let gap1 = |q1: f64| wrapped_deg(q1, seed[0]);
    let ((_, q1, x1), (_, q1_alt, _)) = if gap1(front.1) <= gap1(behind.1) { (front, behind) } else { (behind, front) };
    let [first, second] = elbow(p, x1 - p.a1, wrist.z - p.c1)?;
    let gap23 = |(_, q2, q3): (bool, f64, f64)| wrapped_deg(q2, seed[1]).max(wrapped_deg(q3, seed[2]));
    let (near, far) = if gap23(first) <= gap23(second) { (first, second) } else { (second, first) };
    let (_, q2, q3) = near;
    let w = wrist_rotation(q1, q2 + q3, &rotation);
    if w[(0, 2)].hypot(w[(1, 2)]) <= WRIST_NEAR_SINGULAR {
        return None;
    }
    let [(_, up), (_, down)] = wrist_angles(&w, Some(&seed_rad));
    let gap456 = |q: [f64; 3]| (0..3).map(|i| wrapped_deg(q[i], seed[3 + i])).fold(0.0, f64::max);
    let (wrist_near, wrist_far) = if gap456(up) <= gap456(down) { (up, down) } else { (down, up) };
    let solution = [q1, q2, q3, wrist_near[0], wrist_near[1], wrist_near[2]].map(|q| principal(q).to_degrees());
    let joints = super::turns::nearest_turns(&solution, seed, limits).ok()?;
    let moved = super::turns::distance(&joints, seed);
    let others = gap1(q1_alt).min(gap23(far)).min(gap456(wrist_far));
    (moved < others).then_some(joints)
}

/// How far angle `q` (radians) is from `seed` (degrees), modulo a turn: a lower bound
/// of the move to any turn of `q`.
fn wrapped_deg(q: f64, seed: f64) -> f64 {
    let d = super::wrap(q.to_degrees() - seed, 360.0);
    d.min(360.0 - d)
}

/// Axis 1 for the wrist centre in front of and behind axis 1: (behind, q1, x1) with x1
/// the wrist centre's distance along the arm's plane.
fn axis1(p: &OpwParams, wrist: &Vector3<f64>, seed: Option<&Joints>) -> Option<[(bool, f64, f64); 2]> {
    let rho_sq = wrist.x * wrist.x + wrist.y * wrist.y;
    let reach_sq = rho_sq - p.b * p.b;
    if reach_sq < -SHOULDER_SINGULAR {
        return None;
    }
    let x1 = reach_sq.max(0.0).sqrt();
    let heading = if rho_sq.sqrt() < SHOULDER_SINGULAR {
        // On axis 1 every q1 reaches the wrist centre: keep where the arm is.
        seed.map_or(0.0, |s| s[0])
    } else {
        wrist.y.atan2(wrist.x)
    };
    Some([(false, heading - p.b.atan2(x1), x1), (true, heading - p.b.atan2(-x1), -x1)])
}

/// Axes 2 and 3 for the wrist centre at (dx, dz) from axis 2 in the arm's plane:
/// (behind the lower arm, q2, q3) for both elbows, or `None` out of reach.
fn elbow(p: &OpwParams, dx: f64, dz: f64) -> Option<[(bool, f64, f64); 2]> {
    let k = p.c3.hypot(p.a2);
    let phi = p.a2.atan2(p.c3);
    let dist_sq = dx * dx + dz * dz;
    // Law of cosines with α = q3 + φ the angle of the upper arm off the lower arm's normal.
    let sin_alpha = (p.c2 * p.c2 + k * k - dist_sq) / (2.0 * p.c2 * k);
    if !sin_alpha.is_finite() || sin_alpha.abs() > 1.0 + REACH_SLACK {
        return None;
    }
    let sin_alpha = sin_alpha.clamp(-1.0, 1.0);
    let cos_abs = ((1.0 - sin_alpha) * (1.0 + sin_alpha)).sqrt();
    let solve = |cos_alpha: f64| {
        let q3 = sin_alpha.atan2(cos_alpha) - phi;
        // The wrist centre seen from axis 2 with q2 = 0, turned by q2 onto (dx, dz).
        let (vx, vz) = (k * cos_alpha, p.c2 - k * sin_alpha);
        let q2 = dx.atan2(dz) - vx.atan2(vz);
        (cos_alpha < 0.0, q2, q3)
    };
    Some([solve(cos_abs), solve(-cos_abs)])
}

/// The wrist's rotation relative to the upper arm: Rz(q1)·Ry(q2 + q3 + 90°) undone.
fn wrist_rotation(q1: f64, q23: f64, rotation: &Matrix3<f64>) -> Matrix3<f64> {
    let (s1, c1) = q1.sin_cos();
    let (st, ct) = (q23 + FRAC_PI_2).sin_cos();
    #[rustfmt::skip]
    let arm = Matrix3::new(
        c1 * ct, -s1, c1 * st,
        s1 * ct, c1, s1 * st,
        -st, 0.0, ct,
    );
    arm.transpose() * rotation
}

/// Axes 4, 5, 6 as Z-Y-Z angles: (q5 negative, [q4, q5, q6]) for both wrist flips.
fn wrist_angles(w: &Matrix3<f64>, seed: Option<&Joints>) -> [(bool, [f64; 3]); 2] {
    let sin5 = w[(0, 2)].hypot(w[(1, 2)]);
    if sin5 > WRIST_SINGULAR {
        let q5 = sin5.atan2(w[(2, 2)]);
        let mut q4 = w[(1, 2)].atan2(w[(0, 2)]);
        let mut q6 = w[(2, 1)].atan2(-w[(2, 0)]);
        if let Some(seed) = seed.filter(|_| sin5 < WRIST_NEAR_SINGULAR && w[(2, 2)] > 0.0) {
            // Nearly singular: the split of q4 + q6 is noise, keep axis 4 where it is.
            q6 += q4 - seed[3];
            q4 = seed[3];
            return [(false, [q4, q5, q6]), (true, [q4, -q5, q6])];
        }
        return [(false, [q4, q5, q6]), (true, [q4 + PI, -q5, q6 + PI])];
    }
    // Axes 4 and 6 are parallel: only their sum (q5 = 0) or difference (q5 = 180°) is
    // fixed. Axis 4 keeps the seed's value and axis 6 takes the rest.
    let q4 = seed.map_or(0.0, |s| s[3]);
    let solution = if w[(2, 2)] > 0.0 {
        let sum = w[(1, 0)].atan2(w[(0, 0)]);
        [q4, 0.0, sum - q4]
    } else {
        let diff = (-w[(1, 0)]).atan2(-w[(0, 0)]);
        [q4, PI, q4 - diff]
    };
    // Both flips are the same joints here; the negative one is listed too so a cfx
    // asking for it finds it.
    [(false, solution), (true, solution)]
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
