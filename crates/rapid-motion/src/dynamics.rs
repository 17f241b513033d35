//! Static axis torques from the loads the robot carries (GetMotorTorque): the torque
//! each axis must give to hold point masses still against gravity.
//!
//! What is modelled, and what is not: only the loads declared in RAPID (the tool's
//! `tload`, the payload of GripLoad), each a point mass at its centre of gravity. The
//! arm's own link masses and inertias are not public for ABB robots, nor are friction,
//! the motors' gear ratios and the dynamic (acceleration) torques; they are left out.
//! The robot's base is taken to stand on the floor, world z up.

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
    fn no_loads_or_bad_numbers_give_zero() {
        let kin = default_model().kinematics();
        assert_eq!(holding_torques(&kin, &[0.0; 6], &[]), [0.0; 6]);
        let bad = PointLoad { mass: f64::NAN, cog: Vector3::zeros() };
        assert_eq!(holding_torques(&kin, &[0.0; 6], &[bad]), [0.0; 6]);
        let load = PointLoad { mass: 1.0, cog: Vector3::zeros() };
        assert_eq!(holding_torques(&kin, &[f64::NAN; 6], &[load]), [0.0; 6]);
    }
}
