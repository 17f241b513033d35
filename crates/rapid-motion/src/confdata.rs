//! Robot configuration (RAPID `confdata [cf1, cf4, cf6, cfx]`, motion.md §3.7): what
//! joints a configuration describes, and the choice of the inverse-kinematics solution
//! a programmed configuration asks for (ConfJ\On) or the one closest to the current
//! joints (ConfJ\Off).

use crate::kinematics::{finite_seed, nearest_within_limits, Opw, OpwParams};
use crate::kinematics::{turns_of, Turns};
use crate::{Joints, MotionError, Pose};

/// `[cf1, cf4, cf6, cfx]`: the quadrants of axes 1, 4 and 6 and the arm configuration.
pub type ConfData = [i32; 4];

/// How closely a solution must match a programmed configuration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ConfMatch {
    /// cf1, cf4 and cf6 exactly; cfx equal.
    Exact,
    /// cf1, cf4 and cf6 within one quadrant (an exact match preferred); cfx equal.
    // uncertain: modelled on RobotStudio's `ConfigurationMode.Compliant` (±1 on cf1,
    // cf4, cf6, cfx equal); that the controller's ConfJ\On accepts the same neighbours
    // is not confirmed.
    #[default]
    Compliant,
}

/// The configuration of a joint set: quadrants `floor(q / 90°)` of axes 1, 4 and 6,
/// and cfx from the wrist centre's side of axis 1, its side of the lower arm and the
/// sign of axis 5 (motion.md §3.7 table).
pub fn confdata_of(kin: &Opw, joints: &Joints) -> ConfData {
    if let Some(arm) = kin.seventh() {
        return crate::kinematics::yumi::confdata(&arm.joints7(joints, None));
    }
    let cfx = kin.pallet_cfx(joints).unwrap_or_else(|| cfx_of(kin.params(), joints));
    [quadrant(joints[0]), quadrant(joints[3]), quadrant(joints[5]), cfx]
}

/// The quadrant number of an axis angle: 0 for [0°, 90°), 1 for [90°, 180°), −1 for
/// [−90°, 0°) and so on; 0 for a value that is not a number.
pub fn quadrant(q: f64) -> i32 {
    if !q.is_finite() {
        return 0;
    }
    (q / 90.0).floor().clamp(i32::MIN as f64, i32::MAX as f64) as i32
}

/// cfx = 4·(wrist centre behind axis 1) + 2·(behind the lower arm) + (axis 5 negative).
pub fn cfx_of(p: &OpwParams, joints: &Joints) -> i32 {
    let [_, q2, q3, _, q5, _] = joints.map(f64::to_radians);
    let t = q2 + q3;
    // The wrist centre's coordinate along the arm's plane, from axis 1.
    let along_axis1 = p.a1 + p.c2 * q2.sin() + p.c3 * t.cos() - p.a2 * t.sin();
    // Its side of the line through axes 2 and 3; depends on q3 alone.
    let off_lower_arm = p.c3 * q3.cos() - p.a2 * q3.sin();
    // uncertain: a wrist centre exactly on axis 1 or on the lower arm's line counts as
    // in front, and q5 = 0 as positive; the controller's choice there is not known.
    let behind_axis1 = along_axis1 < 0.0;
    let behind_arm = off_lower_arm < 0.0;
    let negative_q5 = q5 < 0.0;
    4 * behind_axis1 as i32 + 2 * behind_arm as i32 + negative_q5 as i32
}

/// ConfJ\On: the solution with the programmed configuration, the turns of axes 1, 4
/// and 6 chosen by cf1, cf4 and cf6 and, among equals, closest to `seed` (the current
/// joints). Errors as the controller reports them: `OutOfReach` when no configuration
/// reaches the pose, `JointLimit` when the asked one only reaches it outside the
/// limits, `Configuration` when other configurations reach it but not the asked one.
pub fn inverse_conf(
    kin: &Opw,
    flange: &Pose,
    conf: &ConfData,
    seed: &Joints,
    mode: ConfMatch,
) -> Result<Joints, MotionError> {
    let seed = &finite_seed(seed);
    let branches = kin.branches(flange, Some(seed));
    if branches.iter().all(Option::is_none) {
        return Err(MotionError::OutOfReach);
    }
    let cfx = usize::try_from(conf[3]).ok().filter(|&c| c < 8).ok_or(MotionError::Configuration)?;
    // uncertain: when the asked configuration reaches the pose only outside the limits
    // we report the limit (ERR_ROBLIMIT's joint-out-of-range flavour), not the
    // configuration, even if another configuration would be within limits.
    let mut solution = branches[cfx].ok_or(MotionError::Configuration)?;
    let limits = kin.limits_ref();
    if solution[4].abs() < NEAR_SINGULAR_Q5 && kin.pallet().is_none() {
        // At (or, within rounding, near) the wrist singularity axes 4 and 6 can share
        // their sum in any way: share it so both land in the asked quadrants when that
        // is possible.
        if let Some((q4, q6)) = split_wrist(solution[3] + solution[5], conf[1], conf[2], seed[3], limits) {
            solution[3] = q4;
            solution[5] = q6;
        }
    }
    let mut res = [0.0; 6];
    for axis in 0..6 {
        let options = turns_of(solution[axis], limits[axis]);
        if options.as_slice().is_empty() {
            return Err(MotionError::JointLimit { axis: axis + 1 });
        }
        let wanted = match axis {
            0 => Some(conf[0]),
            3 => Some(conf[1]),
            5 => Some(conf[2]),
            _ => None,
        };
        res[axis] = pick_turn(&options, wanted, seed[axis], mode).ok_or(MotionError::Configuration)?;
    }
    Ok(res)
}

/// Axis 5 closer than this to 0 (degrees) is the wrist singularity for the choice of
/// axes 4 and 6: the solver's near-singular band (`WRIST_NEAR_SINGULAR`, 1e-5 rad).
const NEAR_SINGULAR_Q5: f64 = 1e-5 * 180.0 / std::f64::consts::PI;

/// ConfJ\Off: the solution closest to `seed` over every configuration and turn
/// (the same as `Kinematics::inverse_near`).
pub fn inverse_nearest(kin: &Opw, flange: &Pose, seed: &Joints) -> Result<Joints, MotionError> {
    let seed = finite_seed(seed);
    nearest_within_limits(&kin.branches(flange, Some(&seed)), &seed, kin.limits_ref())
}

/// At q5 = 0: q4 in quadrant `cf4` and q6 = sum − q4 (plus turns) in quadrant `cf6`,
/// both within limits, with q4 as close to the seed as that allows.
fn split_wrist(sum: f64, cf4: i32, cf6: i32, seed4: f64, limits: &[(f64, f64); 6]) -> Option<(f64, f64)> {
    let (lo4, hi4) = quadrant_within(cf4, limits[3])?;
    let (lo6, hi6) = quadrant_within(cf6, limits[5])?;
    let mut best: Option<(f64, f64, f64)> = None;
    for turn in -3..=3 {
        let total = sum + 360.0 * f64::from(turn);
        // q6 = total − q4 within [lo6, hi6] ⇔ q4 within [total − hi6, total − lo6].
        let (lo, hi) = (lo4.max(total - hi6), hi4.min(total - lo6));
        if lo > hi {
            continue;
        }
        let q4 = seed4.clamp(lo, hi);
        if best.is_none_or(|(d, _, _)| (q4 - seed4).abs() < d) {
            best = Some(((q4 - seed4).abs(), q4, total - q4));
        }
    }
    best.map(|(_, q4, q6)| (q4, q6))
}

/// The part of quadrant `cf` within the limits, as a closed range just short of the
/// quadrant's upper end (which belongs to the next quadrant).
fn quadrant_within(cf: i32, (lo, hi): (f64, f64)) -> Option<(f64, f64)> {
    let start = 90.0 * f64::from(cf);
    let (a, b) = (start.max(lo), (start + 90.0 - 1e-9).min(hi));
    (a <= b).then_some((a, b))
}

/// The turn in the wanted quadrant (or, compliant, the nearest quadrant within one),
/// closest to the seed; any turn closest to the seed when no quadrant is asked.
fn pick_turn(options: &Turns, wanted: Option<i32>, seed: f64, mode: ConfMatch) -> Option<f64> {
    let max_off = match mode {
        ConfMatch::Exact => 0,
        ConfMatch::Compliant => 1,
    };
    let key = |q: f64| {
        let off = wanted.map_or(0, |w| (i64::from(quadrant(q)) - i64::from(w)).abs());
        (off, (q - seed).abs())
    };
    options.as_slice().iter().copied().filter(|&q| key(q).0 <= max_off).min_by(|&a, &b| {
        let (ka, kb) = (key(a), key(b));
        ka.0.cmp(&kb.0).then(ka.1.total_cmp(&kb.1))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robots::find_model;

    fn irb120() -> Opw {
        find_model("IRB 120").unwrap().kinematics()
    }

    #[test]
    fn quadrants() {
        assert_eq!(quadrant(0.0), 0);
        assert_eq!(quadrant(89.9), 0);
        assert_eq!(quadrant(90.0), 1);
        assert_eq!(quadrant(-0.1), -1);
        assert_eq!(quadrant(-90.0), -1);
        assert_eq!(quadrant(-90.1), -2);
        assert_eq!(quadrant(370.0), 4);
        assert_eq!(quadrant(-400.0), -5);
        assert_eq!(quadrant(f64::NAN), 0);
    }

    #[test]
    fn cfx_of_hand_worked_joints() {
        let kin = irb120();
        // Zero: wrist centre at x = 302 mm in front of axis 1, upper arm horizontal.
        assert_eq!(confdata_of(&kin, &[0.0; 6]), [0, 0, 0, 0]);
        // q5 negative only.
        assert_eq!(confdata_of(&kin, &[0.0, 0.0, 0.0, 0.0, -30.0, -10.0]), [0, 0, -1, 1]);
        // IRB 120 elbow boundary at q3 = −90° + atan(70/302) = −76.95°.
        assert_eq!(cfx_of(kin.params(), &[0.0, 0.0, -76.0, 0.0, 10.0, 0.0]), 0);
        // With q2 = 0 the wrist centre would also be behind axis 1 (x = 62.8 − 68.5 mm);
        // q2 = 30° keeps it in front: x = 135 + 302·cos(−48°) + 70·sin(−48°) = 285 mm.
        assert_eq!(cfx_of(kin.params(), &[0.0, 0.0, -78.0, 0.0, 10.0, 0.0]), 6);
        assert_eq!(cfx_of(kin.params(), &[0.0, 30.0, -78.0, 0.0, 10.0, 0.0]), 2);
        // Lower arm tilted back 80°, upper arm folded up: x = 270·sin(−80°) + … < 0.
        // x = −265.9 + 302·cos(−40°) + 70·sin(−40°) = −265.9 + 231.3 − 45.0 = −79.6.
        assert_eq!(cfx_of(kin.params(), &[0.0, -80.0, 40.0, 0.0, 10.0, 0.0]), 4);
        assert_eq!(confdata_of(&kin, &[100.0, -80.0, 40.0, -100.0, -10.0, 200.0]), [1, -2, 2, 5]);
    }
}
