//! Joint values within limits: the turns (q + k·360°) of an axis that fit its range,
//! and the choice among them that a controller makes when it moves to the closest
//! solution.

use crate::kinematics::Branches;
use crate::{Joints, MotionError};

/// How far (degrees) past a limit still counts as on it, so a pose computed from joints
/// on a limit solves back to them despite rounding.
pub const LIMIT_TOLERANCE: f64 = 1e-7;

/// At most this many turns of one axis are considered; ±400° holds three.
const MAX_TURNS: usize = 4;

/// The turns of one axis value that lie within its limits, lowest first.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Turns {
    values: [f64; MAX_TURNS],
    len: usize,
}

impl Turns {
    pub(crate) fn as_slice(&self) -> &[f64] {
        &self.values[..self.len]
    }
}

pub(crate) fn within(q: f64, lo: f64, hi: f64) -> bool {
    q >= lo - LIMIT_TOLERANCE && q <= hi + LIMIT_TOLERANCE
}

/// Every q + k·360° within [lo, hi], clamped onto a limit it touches within tolerance.
pub(crate) fn turns(q: f64, (lo, hi): (f64, f64)) -> Turns {
    let mut res = Turns { values: [0.0; MAX_TURNS], len: 0 };
    if !q.is_finite() {
        return res;
    }
    let first = ((lo - LIMIT_TOLERANCE - q) / 360.0).ceil();
    for k in 0..MAX_TURNS {
        let value = q + (first + k as f64) * 360.0;
        if !within(value, lo, hi) {
            break;
        }
        res.values[res.len] = value.clamp(lo, hi);
        res.len += 1;
    }
    res
}

/// Adds every combination of turns of `solution` that lies within `limits`.
pub(crate) fn push_all_within(res: &mut Vec<Joints>, solution: &Joints, limits: &[(f64, f64); 6]) {
    let per_axis: [Turns; 6] = std::array::from_fn(|i| turns(solution[i], limits[i]));
    let counts = per_axis.map(|t| t.len);
    if counts.contains(&0) {
        return;
    }
    let total: usize = counts.iter().product();
    for mut n in 0..total {
        let mut joints = [0.0; 6];
        for axis in 0..6 {
            joints[axis] = per_axis[axis].values[n % counts[axis]];
            n /= counts[axis];
        }
        res.push(joints);
    }
}

/// The turn of each axis closest to `seed`, or the 1-based axis that has none.
pub(crate) fn nearest_turns(solution: &Joints, seed: &Joints, limits: &[(f64, f64); 6]) -> Result<Joints, usize> {
    let mut res = [0.0; 6];
    for axis in 0..6 {
        let options = turns(solution[axis], limits[axis]);
        let best =
            options.as_slice().iter().copied().min_by(|a, b| (a - seed[axis]).abs().total_cmp(&(b - seed[axis]).abs()));
        res[axis] = best.ok_or(axis + 1)?;
    }
    Ok(res)
}

/// The largest single-axis move from `seed` to `joints`, degrees.
pub(crate) fn distance(joints: &Joints, seed: &Joints) -> f64 {
    joints.iter().zip(seed).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
}

/// The solution, over all branches and turns within limits, whose largest single-axis
/// move from `seed` is smallest (ConfJ\Off). Errors: `OutOfReach` when no branch
/// reaches the pose, `JointLimit` with the axis that stops the branch closest to the
/// seed when every branch leaves the limits.
pub fn nearest_within_limits(
    branches: &Branches,
    seed: &Joints,
    limits: &[(f64, f64); 6],
) -> Result<Joints, MotionError> {
    let mut best: Option<(f64, Joints)> = None;
    let mut blocked: Option<(f64, usize)> = None;
    for solution in branches.iter().flatten() {
        match nearest_turns(solution, seed, limits) {
            Ok(joints) => {
                let d = distance(&joints, seed);
                if best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, joints));
                }
            }
            Err(axis) => {
                let d = wrapped_distance(solution, seed);
                if blocked.is_none_or(|(b, _)| d < b) {
                    blocked = Some((d, axis));
                }
            }
        }
    }
    match (best, blocked) {
        (Some((_, joints)), _) => Ok(joints),
        (None, Some((_, axis))) => Err(MotionError::JointLimit { axis }),
        (None, None) => Err(MotionError::OutOfReach),
    }
}

/// The largest single-axis angle between two joint sets, each axis taken modulo 360°.
fn wrapped_distance(joints: &Joints, seed: &Joints) -> f64 {
    joints.iter().zip(seed).map(|(a, b)| super::wrap(a - b, 360.0).min(super::wrap(b - a, 360.0))).fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turns_of_a_400_degree_axis() {
        assert_eq!(turns(10.0, (-400.0, 400.0)).as_slice(), &[-350.0, 10.0, 370.0]);
        assert_eq!(turns(50.0, (-400.0, 400.0)).as_slice(), &[-310.0, 50.0]);
        assert_eq!(turns(40.0, (-400.0, 400.0)).as_slice(), &[-320.0, 40.0, 400.0]);
        assert_eq!(turns(170.0, (-160.0, 160.0)).as_slice(), &[] as &[f64]);
        assert_eq!(turns(f64::NAN, (-160.0, 160.0)).as_slice(), &[] as &[f64]);
        assert_eq!(turns(-180.0, (-180.0, 180.0)).as_slice(), &[-180.0, 180.0]);
    }

    #[test]
    fn nearest_turn_follows_the_seed() {
        let limits =
            [(-180.0, 180.0), (-90.0, 150.0), (-180.0, 75.0), (-400.0, 400.0), (-125.0, 120.0), (-400.0, 400.0)];
        let solution = [0.0, 0.0, 0.0, 10.0, 20.0, -30.0];
        let seed = [0.0, 0.0, 0.0, 300.0, 0.0, -300.0];
        assert_eq!(nearest_turns(&solution, &seed, &limits), Ok([0.0, 0.0, 0.0, 370.0, 20.0, -390.0]));
    }

    #[test]
    fn errors_name_the_blocking_axis() {
        let limits =
            [(-165.0, 165.0), (-110.0, 110.0), (-110.0, 70.0), (-160.0, 160.0), (-120.0, 120.0), (-400.0, 400.0)];
        let mut branches: Branches = [None; 8];
        assert_eq!(nearest_within_limits(&branches, &[0.0; 6], &limits), Err(MotionError::OutOfReach));
        branches[0] = Some([0.0, 0.0, 80.0, 0.0, 0.0, 0.0]);
        branches[3] = Some([0.0, 0.0, 0.0, 170.0, 0.0, 0.0]);
        assert_eq!(nearest_within_limits(&branches, &[0.0; 6], &limits), Err(MotionError::JointLimit { axis: 3 }));
    }
}
