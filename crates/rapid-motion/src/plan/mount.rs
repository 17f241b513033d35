//! How a move's path relates to the robot's flange. With a robot-held tool the path
//! is the TCP in the base frame. With a stationary tool (`robhold` FALSE) the robot
//! carries the work object past a TCP fixed in the room, and the path is the TCP's
//! pose in the moving object frame: a linear move is a straight line of the tool over
//! the workpiece, whatever the flange does.

use crate::Pose;

/// The relation between a path pose and the flange pose (both in the base frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mount {
    /// The tool is on the flange: path pose (the TCP) = flange · tool.
    Held(Pose),
    /// The tool stands still at `tcp` (base frame) and the robot holds the work
    /// object, `object` being its frame in the flange frame (user, object and
    /// displacement frames together): path pose = (flange · object)⁻¹ · tcp.
    Stationary { tcp: Pose, object: Pose },
}

impl Mount {
    /// The path pose the flange pose gives.
    pub fn path_pose(&self, flange: &Pose) -> Pose {
        match self {
            Mount::Held(tool) => flange * tool,
            Mount::Stationary { tcp, object } => (flange * object).inverse() * tcp,
        }
    }

    /// The flange pose that puts the path at `path_pose`.
    pub fn flange(&self, path_pose: &Pose) -> Pose {
        match self {
            Mount::Held(tool) => path_pose * tool.inverse(),
            Mount::Stationary { tcp, object } => tcp * path_pose.inverse() * object.inverse(),
        }
    }

    /// The TCP in the base frame for a flange pose (a stationary TCP never moves).
    pub fn tcp(&self, flange: &Pose) -> Pose {
        match self {
            Mount::Held(tool) => flange * tool,
            Mount::Stationary { tcp, .. } => *tcp,
        }
    }

    /// Whether every number in it is finite.
    pub(crate) fn is_finite(&self) -> bool {
        let ok = |p: &Pose| p.translation.vector.iter().chain(p.rotation.coords.iter()).all(|x| x.is_finite());
        match self {
            Mount::Held(tool) => ok(tool),
            Mount::Stationary { tcp, object } => ok(tcp) && ok(object),
        }
    }

    /// Whether two moves share one mount (a TCP corner path may join them).
    pub(crate) fn same_as(&self, other: &Mount) -> bool {
        match (self, other) {
            (Mount::Held(a), Mount::Held(b)) => same_pose(a, b),
            (Mount::Stationary { tcp: a, object: c }, Mount::Stationary { tcp: b, object: d }) => {
                same_pose(a, b) && same_pose(c, d)
            }
            _ => false,
        }
    }
}

/// Whether two poses coincide (to a nanometre and a nanoradian).
pub(crate) fn same_pose(a: &Pose, b: &Pose) -> bool {
    (a.translation.vector - b.translation.vector).norm() < 1e-9 && a.rotation.angle_to(&b.rotation) < 1e-9
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pose::pose;

    #[test]
    fn flange_and_path_pose_are_inverse_for_both_mounts() {
        let flange = pose([400.0, 50.0, 300.0], [0.0, 0.6, 0.8, 0.0]);
        let tool = pose([0.0, 0.0, 120.0], [1.0, 0.0, 0.0, 0.0]);
        let stationary = Mount::Stationary {
            tcp: pose([600.0, 0.0, 200.0], [0.0, 0.0, 1.0, 0.0]),
            object: pose([10.0, 20.0, 80.0], [0.9238795, 0.0, 0.0, 0.3826834]),
        };
        for mount in [Mount::Held(tool), stationary] {
            let back = mount.flange(&mount.path_pose(&flange));
            assert!((back.translation.vector - flange.translation.vector).norm() < 1e-9);
            assert!(back.rotation.angle_to(&flange.rotation) < 1e-9);
        }
        // A stationary tool: the object point under the TCP, carried by the flange,
        // lands on the TCP.
        let Mount::Stationary { tcp, object } = stationary else { unreachable!() };
        let on_object = stationary.path_pose(&flange);
        let landed = flange * object * on_object;
        assert!((landed.translation.vector - tcp.translation.vector).norm() < 1e-9);
    }
}
