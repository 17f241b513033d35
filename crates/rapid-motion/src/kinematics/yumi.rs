//! The IRB 14000 YuMi: two 7-axis arms (ROB_L, ROB_R) on one body. Each arm's
//! forward kinematics from the body's base frame (where both arms' robtargets are
//! given), the arm angle that names the redundant 7th degree of freedom
//! (`robtarget.extax.eax_a`), and a numeric inverse kinematics with the arm angle given.
//!
//! Axis numbering is ABB's: axes 1..6 are `jointtarget.robax.rax_1..rax_6` and axis 7
//! (`extax.eax_a`) is physically the arm's third joint, between axis 2 and axis 3. The
//! public ROS descriptions name their joints the same way (joint order along the chain
//! 1, 2, 7, 3, 4, 5, 6; e.g. ABB's ROS driver joint lists in Gabrieleenx/yumi_dlo_thesis
//! yumi_description/README.md and ilVecc/yumift yumi_description/urdf/yumi.xacro).
//!
//! Link geometry: the joint origins of the YuMi URDF (kth-ros-pkg/yumi, as carried in
//! ilVecc/yumift yumi_description/urdf/yumi.xacro; OrebroUniversity/yumi has the same
//! numbers for the first four joints), in millimetres. Each joint is the URDF's: a
//! fixed origin (translation, then roll-pitch-yaw), then a turn about its own z.
//!
//! In RAPID (checked against public YuMi programs and backups): a jointtarget carries
//! axis 7 in `extax.eax_a` (yumipy's RAPID servers read `CJointT().extax.eax_a` as
//! "joint 7"; a public backup's MOC.cfg configures axis 7 as a `SINGLE` `ROB_R_7` /
//! `ROB_L_7` beside the six `-use_joint_n` of `ROBOT`), and a robtarget carries the
//! arm angle in `extax.eax_a`: the same backup moves MoveAbsJ with eax_a −58.7° and
//! MoveL with eax_a −173.7° to one place, so the robtarget's value is no axis value.
// uncertain: tool0 is taken to be the URDF's last link frame (link_7); the URDF's zero
// is taken to be ABB's axis zero (ABB's ROS driver passes joint values through
// unchanged). ABB's calibration position is elsewhere ([`calibration`]).

use std::f64::consts::PI;

use nalgebra::{Isometry3, SMatrix, SVector, Translation3, UnitQuaternion, Vector3};

use crate::{MotionError, Pose};

/// A YuMi arm's seven axes in ABB's numbering, degrees: axes 1..6, then axis 7 (the
/// physical third joint).
pub type Joints7 = [f64; 7];

/// Which arm of the YuMi.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// ROB_L, the robot's left arm (+y of the body).
    Left,
    /// ROB_R, the robot's right arm (−y of the body).
    Right,
}

/// One joint of the chain: where its frame sits on the previous one (mm, and roll,
/// pitch, yaw in radians as the URDF writes them).
struct Origin {
    xyz: [f64; 3],
    rpy: [f64; 3],
}

const fn origin(xyz: [f64; 3], rpy: [f64; 3]) -> Origin {
    Origin { xyz, rpy }
}

const H: f64 = PI / 2.0;

/// Axis 1 on the body, per arm (URDF `yumi_joint_1_r` / `yumi_joint_1_l`).
const BASE_RIGHT: Origin = origin([53.55, -72.5, 414.92], [-0.9795, -0.5682, -2.3155]);
const BASE_LEFT: Origin = origin([53.55, 72.5, 414.92], [0.9781, -0.5716, 2.3180]);

/// The joints after axis 1, in chain order: axis 2, axis 7, axis 3, axis 4, axis 5,
/// axis 6 (URDF joints 2, 7, 3, 4, 5, 6; the same on both arms).
const CHAIN: [Origin; 6] = [
    origin([30.0, 0.0, 100.0], [H, 0.0, 0.0]),
    origin([-30.0, 172.83, 0.0], [-H, 0.0, 0.0]),
    origin([-41.88, 0.0, 78.73], [H, -H, 0.0]),
    origin([40.5, 164.61, 0.0], [-H, 0.0, 0.0]),
    origin([-27.0, 0.0, 100.39], [H, 0.0, 0.0]),
    origin([27.0, 29.0, 0.0], [-H, 0.0, 0.0]),
];

/// The ABB axis (0-based index into [`Joints7`]) each chain joint turns: axis 1, 2,
/// 7, 3, 4, 5, 6.
const CHAIN_AXIS: [usize; 7] = [0, 1, 6, 2, 3, 4, 5];

/// The axis ranges of the IRB 14000 in ABB's numbering (axes 1..6, then 7), degrees:
/// ABB's product specification as the public URDFs carry it (±168.5°, −143.5..43.5°,
/// −123.5..80°, ±290°, −88..138°, ±229°, and ±168.5° on axis 7).
pub const LIMITS: [(f64, f64); 7] = [
    (-168.5, 168.5),
    (-143.5, 43.5),
    (-123.5, 80.0),
    (-290.0, 290.0),
    (-88.0, 138.0),
    (-229.0, 229.0),
    (-168.5, 168.5),
];

/// The axis speeds, °/s, in the same order: 180 on axes 1, 2, 3 and 7, 400 on the
/// wrist (the URDFs' velocity limits).
pub const SPEEDS: [f64; 7] = [180.0, 180.0, 180.0, 400.0, 400.0, 400.0, 180.0];

/// The calibration position of arm `side` (axes 1..6, then 7): axes 2, 3, 5 at −130°,
/// 30°, 40° and axis 7 at −135° (right) or 135° (left), the others 0 — the
/// `-cal_position` values (radians) of a public YuMi backup's MOC.cfg `ARM` entries,
/// the same as its programs' home MoveAbsJ `[[0,-130,30,0,40,0],[∓135,9E9,…]]`.
pub fn calibration(side: Side) -> Joints7 {
    let q7 = match side {
        Side::Right => -135.0,
        Side::Left => 135.0,
    };
    [0.0, -130.0, 30.0, 0.0, 40.0, 0.0, q7]
}

fn transform(o: &Origin) -> Isometry3<f64> {
    let [r, p, y] = o.rpy;
    Isometry3::from_parts(Translation3::new(o.xyz[0], o.xyz[1], o.xyz[2]), UnitQuaternion::from_euler_angles(r, p, y))
}

fn turn(q_deg: f64) -> Isometry3<f64> {
    Isometry3::rotation(Vector3::z() * q_deg.to_radians())
}

/// Axis 1's frame on the body of arm `side`.
pub fn base(side: Side) -> Pose {
    transform(match side {
        Side::Left => &BASE_LEFT,
        Side::Right => &BASE_RIGHT,
    })
}

/// The frame of every chain joint (after its turn) in the body frame: axis 1's, axis
/// 2's, axis 7's, axis 3's, axis 4's, axis 5's and the flange (after axis 6).
fn frames(side: Side, joints: &Joints7) -> [Pose; 7] {
    let mut frame = base(side) * turn(joints[CHAIN_AXIS[0]]);
    let mut res = [frame; 7];
    for (k, o) in CHAIN.iter().enumerate() {
        frame = frame * transform(o) * turn(joints[CHAIN_AXIS[k + 1]]);
        res[k + 1] = frame;
    }
    res
}

/// tool0 of arm `side` in the body frame, mm.
pub fn forward(side: Side, joints: &Joints7) -> Pose {
    frames(side, joints)[6]
}

/// The arm angle, degrees in (−180°, 180°]: how far the elbow (axis 3) is turned about
/// the line from the shoulder (axis 2) to the wrist (axis 5), measured from the plane
/// that line makes with axis 1, positive by the right hand about the shoulder→wrist
/// line. 0 at the calibration position (the elbow on axis 1's side of the line, away
/// from the body's floor).
// uncertain: ABB's product manual defines the arm angle by a reference plane whose
// exact construction is not public; this is our reading (0 at the calibration
// position, turning with the elbow about the shoulder–wrist line).
pub fn arm_angle(side: Side, joints: &Joints7) -> f64 {
    let f = frames(side, joints);
    let axis1 = f[0].rotation * Vector3::z();
    let shoulder = f[1].translation.vector;
    let elbow = f[3].translation.vector;
    let wrist = f[5].translation.vector;
    angle_about(&shoulder, &elbow, &wrist, &axis1).to_degrees()
}

/// The angle of `elbow` about the line shoulder→wrist, from the half-plane towards
/// `reference` (radians).
fn angle_about(shoulder: &Vector3<f64>, elbow: &Vector3<f64>, wrist: &Vector3<f64>, reference: &Vector3<f64>) -> f64 {
    let u = (wrist - shoulder).try_normalize(1e-9).unwrap_or_else(Vector3::z);
    let perp = |v: &Vector3<f64>| v - u * u.dot(v);
    let mut r = perp(reference);
    if r.norm() < 1e-9 {
        // The shoulder–wrist line along axis 1: any plane will do; take x.
        r = perp(&Vector3::x());
    }
    let e = perp(&(elbow - shoulder));
    u.dot(&r.cross(&e)).atan2(r.dot(&e))
}

/// How close the inverse kinematics must come: mm, radians, radians.
const POSITION_TOLERANCE: f64 = 1e-6;
const ANGLE_TOLERANCE: f64 = 1e-8;
/// Iterations per start, and the starts tried (the seed first).
const ITERATIONS: usize = 400;
/// mm per radian: weighs orientation and arm-angle errors against position errors.
const LEVER: f64 = 200.0;

/// The joints within [`LIMITS`] that put tool0 of arm `side` at `flange` (body frame,
/// mm) with arm angle `angle` (degrees), found by damped least squares from `seed`
/// (and, failing that, a few fixed starts). `OutOfReach` when no start converges.
pub fn inverse(side: Side, flange: &Pose, angle: f64, seed: &Joints7) -> Result<Joints7, MotionError> {
    let finite = flange.translation.vector.iter().all(|v| v.is_finite())
        && flange.rotation.coords.iter().all(|v| v.is_finite())
        && angle.is_finite();
    if !finite {
        return Err(MotionError::OutOfReach);
    }
    let seed = clamp(&seed.map(|q| if q.is_finite() { q } else { 0.0 }));
    let mut starts = vec![seed];
    for k in [-1.0, 1.0] {
        let mut s = seed;
        s[6] = (s[6] + 45.0 * k).clamp(LIMITS[6].0, LIMITS[6].1);
        starts.push(s);
    }
    starts.push([0.0, -60.0, 20.0, 0.0, 40.0, 0.0, 0.0]);
    starts.into_iter().find_map(|start| descend(side, flange, angle.to_radians(), start)).ok_or(MotionError::OutOfReach)
}

/// The task error of `joints`: position (mm), orientation (rotation vector times
/// [`LEVER`]) and arm angle (radians times [`LEVER`]).
fn error(side: Side, flange: &Pose, angle: f64, joints: &Joints7) -> SVector<f64, 7> {
    let now = forward(side, joints);
    let dp = flange.translation.vector - now.translation.vector;
    let dr = (flange.rotation * now.rotation.inverse()).scaled_axis() * LEVER;
    let da = principal(angle - arm_angle(side, joints).to_radians()) * LEVER;
    SVector::<f64, 7>::from_column_slice(&[dp.x, dp.y, dp.z, dr.x, dr.y, dr.z, da])
}

/// Damped least squares from `start`, the joints clamped to their limits after every
/// step; `None` when it does not converge within [`ITERATIONS`].
fn descend(side: Side, flange: &Pose, angle: f64, start: Joints7) -> Option<Joints7> {
    let mut q = start;
    let mut lambda = 1.0;
    let mut e = error(side, flange, angle, &q);
    for _ in 0..ITERATIONS {
        if converged(&e) {
            return Some(q);
        }
        let jac = jacobian(side, flange, angle, &q);
        let damped = jac * jac.transpose() + SMatrix::<f64, 7, 7>::identity() * (lambda * lambda);
        let step = jac.transpose() * damped.try_inverse()? * e;
        let next = clamp(&std::array::from_fn(|i| q[i] + step[i].to_degrees()));
        let next_e = error(side, flange, angle, &next);
        if next_e.norm() < e.norm() {
            q = next;
            e = next_e;
            lambda = (lambda * 0.5).max(1e-6);
        } else {
            lambda *= 2.0;
            if lambda > 1e6 {
                return None;
            }
        }
    }
    converged(&e).then_some(q)
}

fn converged(e: &SVector<f64, 7>) -> bool {
    let p = e.fixed_rows::<3>(0).norm();
    let r = e.fixed_rows::<4>(3).norm() / LEVER;
    p < POSITION_TOLERANCE && r < ANGLE_TOLERANCE
}

/// The Jacobian of the task error's decrease with respect to each joint (radians), by
/// central differences.
fn jacobian(side: Side, flange: &Pose, angle: f64, q: &Joints7) -> SMatrix<f64, 7, 7> {
    let h = 1e-6_f64.to_degrees();
    let mut jac = SMatrix::<f64, 7, 7>::zeros();
    for i in 0..7 {
        let (mut plus, mut minus) = (*q, *q);
        plus[i] += h;
        minus[i] -= h;
        // The error decreases as the pose approaches: the column is −d(error)/dq.
        let col = (error(side, flange, angle, &minus) - error(side, flange, angle, &plus)) / 2e-6;
        jac.set_column(i, &col);
    }
    jac
}

fn clamp(q: &Joints7) -> Joints7 {
    std::array::from_fn(|i| q[i].clamp(LIMITS[i].0, LIMITS[i].1))
}

/// Axes 1..6 that put tool0 of arm `side` at `flange` (body frame, mm) with axis 7
/// held at `q7`, found by damped least squares from `seed` (and, failing that, a few
/// fixed starts): the arm on a path where axis 7's value is given. `OutOfReach` when no
/// start converges within [`LIMITS`].
pub fn inverse_locked(side: Side, flange: &Pose, q7: f64, seed: &[f64; 6]) -> Result<[f64; 6], MotionError> {
    let finite = flange.translation.vector.iter().all(|v| v.is_finite())
        && flange.rotation.coords.iter().all(|v| v.is_finite())
        && q7.is_finite();
    if !finite {
        return Err(MotionError::OutOfReach);
    }
    let seed: [f64; 6] = std::array::from_fn(|i| {
        let q = if seed[i].is_finite() { seed[i] } else { 0.0 };
        q.clamp(LIMITS[i].0, LIMITS[i].1)
    });
    let home = calibration(side);
    let starts = [seed, [home[0], home[1], home[2], home[3], home[4], home[5]], [0.0, -60.0, 20.0, 0.0, 40.0, 0.0]];
    starts.into_iter().find_map(|start| descend_locked(side, flange, q7, start)).ok_or(MotionError::OutOfReach)
}

/// The pose error of axes `q` with axis 7 at `q7`: position (mm) and orientation
/// (rotation vector times [`LEVER`]).
fn pose_error(side: Side, flange: &Pose, q7: f64, q: &[f64; 6]) -> SVector<f64, 6> {
    let now = forward(side, &[q[0], q[1], q[2], q[3], q[4], q[5], q7]);
    let dp = flange.translation.vector - now.translation.vector;
    let dr = (flange.rotation * now.rotation.inverse()).scaled_axis() * LEVER;
    SVector::<f64, 6>::from_column_slice(&[dp.x, dp.y, dp.z, dr.x, dr.y, dr.z])
}

/// [`descend`] over axes 1..6 with axis 7 held.
fn descend_locked(side: Side, flange: &Pose, q7: f64, start: [f64; 6]) -> Option<[f64; 6]> {
    let done = |e: &SVector<f64, 6>| {
        e.fixed_rows::<3>(0).norm() < POSITION_TOLERANCE && e.fixed_rows::<3>(3).norm() / LEVER < ANGLE_TOLERANCE
    };
    let (mut q, mut lambda) = (start, 1.0);
    let mut e = pose_error(side, flange, q7, &q);
    for _ in 0..ITERATIONS {
        if done(&e) {
            return Some(q);
        }
        let mut jac = SMatrix::<f64, 6, 6>::zeros();
        for i in 0..6 {
            let (mut plus, mut minus) = (q, q);
            plus[i] += 1e-6_f64.to_degrees();
            minus[i] -= 1e-6_f64.to_degrees();
            let col = (pose_error(side, flange, q7, &minus) - pose_error(side, flange, q7, &plus)) / 2e-6;
            jac.set_column(i, &col);
        }
        let damped = jac * jac.transpose() + SMatrix::<f64, 6, 6>::identity() * (lambda * lambda);
        let step = jac.transpose() * damped.try_inverse()? * e;
        let next: [f64; 6] = std::array::from_fn(|i| (q[i] + step[i].to_degrees()).clamp(LIMITS[i].0, LIMITS[i].1));
        let next_e = pose_error(side, flange, q7, &next);
        if next_e.norm() < e.norm() {
            (q, e) = (next, next_e);
            lambda = (lambda * 0.5).max(1e-6);
        } else {
            lambda *= 2.0;
            if lambda > 1e6 {
                return None;
            }
        }
    }
    done(&e).then_some(q)
}

/// The confdata `[cf1, cf4, cf6, cfx]` the controller reports for a YuMi arm's axes.
/// cf1, cf4 and cf6 are the quadrants of axes 1, 4 and 6 (`floor(q / 90°)`, RAPID's
/// general rule); cfx is 4, plus 1 when axis 5 is negative.
// uncertain: the public record does not settle the YuMi's convention. Every robtarget
// of the public programs we read has cfx 4 or 5, 5 exactly where the neighbouring
// MoveAbsJ has axis 5 negative, so bit 0 reads as the OPW arms' (axis 5 negative) and
// bit 2 as always set there; one target with a matching MoveAbsJ (axes 64.5°, …,
// 155.4°, …, 7.6°) reports cf1 = 1 and cf4 = 2 where floor gives 0 and 1 (rounding to
// the nearest quarter turn would give them), so cf1/cf4/cf6 are uncertain too. RobotWare
// also has an "old" arm-angle definition whose targets carry another cfx (event 50488).
// Moves of a YuMi arm do not choose their solution by confdata: the arm angle and the
// axes nearest the current ones do.
pub fn confdata(joints: &Joints7) -> [i32; 4] {
    let quadrant = |q: f64| if q.is_finite() { (q / 90.0).floor().clamp(-1e9, 1e9) as i32 } else { 0 };
    [quadrant(joints[0]), quadrant(joints[3]), quadrant(joints[5]), 4 + i32::from(joints[4] < 0.0)]
}

/// The angle in (−π, π].
fn principal(a: f64) -> f64 {
    let r = super::wrap(a + PI, 2.0 * PI) - PI;
    if r <= -PI {
        r + 2.0 * PI
    } else {
        r
    }
}

/// The 1-based ABB axis of the first joint outside [`LIMITS`] (axis 7 is 7).
pub fn limit_violation(joints: &Joints7) -> Option<usize> {
    joints.iter().zip(&LIMITS).position(|(q, &(lo, hi))| !(lo - 1e-9..=hi + 1e-9).contains(q)).map(|i| i + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn principal_wraps_into_the_half_open_range() {
        assert!((principal(3.0 * PI) - PI).abs() < 1e-12);
        assert!((principal(-PI) - PI).abs() < 1e-12);
        assert!((principal(0.25) - 0.25).abs() < 1e-12);
    }
}
