//! Axis torques from the loads the robot carries (GetMotorTorque): the torque each axis
//! must give to hold point masses against gravity and, while the robot moves, to
//! accelerate them along their paths.
//!
//! What is modelled, and what is not: only the loads declared in RAPID (the tool's
//! `tload`, the payload of GripLoad), each a point mass at its centre of gravity. The
//! arm's own link masses and inertias are not public for ABB robots, nor are friction
//! and the motors' gear ratios; the loads' own rotational inertia (`ix`, `iy`, `iz`) is
//! left out too. The robot's base is taken to stand on the floor, world z up.

use nalgebra::{Point3, Vector3};

use crate::{Joints, Kinematics};

/// Standard gravity, m/s².
pub const GRAVITY: f64 = 9.81;

/// A point mass the flange carries: kg, centre of gravity in the flange frame, mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointLoad {
    pub mass: f64,
    pub cog: Vector3<f64>,
}

/// The step of the numerical derivative, degrees.
const STEP_DEG: f64 = 1e-4;

/// The torque (Nm) each axis must give to hold the loads still at `joints`: the
/// negative of gravity's generalised force, m·g·∂z/∂q summed over the loads (z of the
/// centre of gravity in metres, q in radians). Axes the loads cannot turn get 0; a
/// load that is not a number adds nothing.
pub fn holding_torques(kin: &dyn Kinematics, joints: &Joints, loads: &[PointLoad]) -> [f64; 6] {
    let mut torques = [0.0; 6];
    let loads: Vec<&PointLoad> =
        loads.iter().filter(|l| l.mass.is_finite() && l.cog.iter().all(|c| c.is_finite())).collect();
    if loads.is_empty() || !joints.iter().all(|q| q.is_finite()) {
        return torques;
    }
    let height = |q: &Joints, load: &PointLoad| (kin.forward(q) * Point3::from(load.cog)).z;
    for (axis, torque) in torques.iter_mut().enumerate() {
        let mut up = *joints;
        let mut down = *joints;
        up[axis] += STEP_DEG;
        down[axis] -= STEP_DEG;
        for load in &loads {
            // Central difference: mm per degree, to m per radian.
            let dz_dq =
                (height(&up, load) - height(&down, load)) / (2.0 * STEP_DEG) * (180.0 / std::f64::consts::PI) / 1000.0;
            *torque += load.mass * GRAVITY * dz_dq;
        }
    }
    torques
}

/// The torque (Nm) each axis gives at the middle of `joints` (the axis values at
/// t − h, t and t + h, `h` in seconds) to hold the loads against gravity and give them
/// the acceleration they have there: m·(a + g·ẑ)·∂p/∂q summed over the loads, with `a`
/// the second difference of each centre of gravity's position.
pub fn moving_torques(kin: &dyn Kinematics, joints: &[Joints; 3], h: f64, loads: &[PointLoad]) -> [f64; 6] {
    let [before, now, after] = joints;
    let mut torques = holding_torques(kin, now, loads);
    let moving = before != now || after != now;
    let usable = moving && h.is_finite() && h > 0.0 && joints.iter().flatten().all(|q| q.is_finite());
    if !usable {
        return torques;
    }
    let at = |q: &Joints, load: &PointLoad| (kin.forward(q) * Point3::from(load.cog)).coords;
    for load in loads.iter().filter(|l| l.mass.is_finite() && l.cog.iter().all(|c| c.is_finite())) {
        // mm/s² to m/s².
        let accel = (at(after, load) - 2.0 * at(now, load) + at(before, load)) / (h * h) / 1000.0;
        for (axis, torque) in torques.iter_mut().enumerate() {
            let (mut up, mut down) = (*now, *now);
            up[axis] += STEP_DEG;
            down[axis] -= STEP_DEG;
            // m per radian.
            let dp_dq = (at(&up, load) - at(&down, load)) / (2.0 * STEP_DEG) * (180.0 / std::f64::consts::PI) / 1000.0;
            *torque += load.mass * accel.dot(&dp_dq);
        }
    }
    torques
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robots::default_model;

    #[test]
    fn one_kilogram_ahead_of_the_flange_at_calibration_position() {
        // IRB 120 at all axes 0: the flange at (374, 0, 630) mm with its z axis along
        // world x, so a load 100 mm out on flange z sits at (474, 0, 630). Axes 2 and 3
        // turn about world y through (0, 0, 290) and (0, 0, 560): a positive turn moves
        // the load down at the rate of its x distance, 474 mm/rad; axis 5 turns about y
        // through the wrist centre (302, 0, 630): 172 mm/rad. Axes 1, 4, 6 do not lift
        // it. Holding torque = 1 kg × 9.81 × (−dz/dq): −4.64994, −4.64994, −1.68732 Nm.
        let kin = default_model().kinematics();
        let load = PointLoad { mass: 1.0, cog: Vector3::new(0.0, 0.0, 100.0) };
        let t = holding_torques(&kin, &[0.0; 6], &[load]);
        let expected = [0.0, -4.64994, -4.64994, 0.0, -1.68732, 0.0];
        for (got, want) in t.iter().zip(expected) {
            assert!((got - want).abs() < 1e-4, "{t:?}");
        }
    }

    #[test]
    fn accelerating_axis_1_takes_m_r_squared_alpha() {
        // Axis 1 accelerating at 1 rad/s² through 0 with 1 kg 474 mm from its axis (100 mm
        // out on flange z at the calibration position): the load needs m·r·α tangentially,
        // so axis 1 gives m·r²·α = 0.474² = 0.224676 Nm (gravity needs nothing of it).
        // Sampled 1 ms apart: ±0.5e-6 rad from 0, i.e. q(t) = α·t²/2.
        let kin = default_model().kinematics();
        let load = PointLoad { mass: 1.0, cog: Vector3::new(0.0, 0.0, 100.0) };
        let h = 0.001;
        let q = |rad: f64| [rad.to_degrees(), 0.0, 0.0, 0.0, 0.0, 0.0];
        let t = moving_torques(&kin, &[q(0.5 * h * h), q(0.0), q(0.5 * h * h)], h, &[load]);
        assert!((t[0] - 0.224676).abs() < 1e-3, "{t:?}");
        // Standing still, the holding torques alone.
        let still = moving_torques(&kin, &[[0.0; 6]; 3], h, &[load]);
        assert_eq!(still, holding_torques(&kin, &[0.0; 6], &[load]));
    }

    #[test]
    fn no_loads_or_bad_numbers_give_zero() {
        let kin = default_model().kinematics();
        assert_eq!(holding_torques(&kin, &[0.0; 6], &[]), [0.0; 6]);
        let bad = PointLoad { mass: f64::NAN, cog: Vector3::zeros() };
        assert_eq!(holding_torques(&kin, &[0.0; 6], &[bad]), [0.0; 6]);
        let load = PointLoad { mass: 1.0, cog: Vector3::zeros() };
        assert_eq!(holding_torques(&kin, &[f64::NAN; 6], &[load]), [0.0; 6]);
    }
}
