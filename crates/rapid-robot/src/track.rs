//! A track the robot stands on (a unit with `carries_robot`): its linear axis moves the
//! robot's base frame, so targets in the world are reached with the base where the track
//! will be, and a linear move keeps its world line and TCP speed.

use rapid_motion::external::{is_unused, ExternalMove};

use super::extax::ExternalUnits;

impl ExternalUnits {
    /// The track the robot stands on, if any: its axis (`extjoint` index) and the
    /// world direction it moves the robot's base along.
    pub fn track(&self) -> Option<(usize, nalgebra::Vector3<f64>)> {
        let unit = &self.units.iter().find(|u| u.unit.carries_robot)?.unit;
        let axis = unit.axes.first()?;
        let dir = unit.frame.map_or(nalgebra::Vector3::x(), |f| f.rotation * nalgebra::Vector3::x());
        Some((axis.index(), dir))
    }
}

impl super::robot::RobotState {
    /// The robot's base frame in the world with its track at `eax`: its configured base
    /// frame, moved along the track by the track's value (a value of 9E9 is where the
    /// track stands at the end of the planned moves).
    pub fn track_base(&self, eax: &[f64; 6]) -> rapid_motion::Pose {
        let Some((axis, dir)) = self.external.track() else { return self.base_frame };
        let mut at = eax[axis];
        if is_unused(at) {
            at = self.planner.end_eax().map_or(0.0, |e| e[axis]);
        }
        let along = nalgebra::Translation3::from(dir * at);
        rapid_motion::Pose::from_parts(along, nalgebra::UnitQuaternion::identity()) * self.base_frame
    }

    /// A direction in the world as the robot's base frame sees it.
    pub(super) fn in_base(&self, world: nalgebra::Vector3<f64>) -> nalgebra::Vector3<f64> {
        self.base_frame.rotation.inverse() * world
    }

    /// The robot's base frame in the world at controller time `t`.
    pub fn track_base_at(&self, t: f64) -> rapid_motion::Pose {
        match self.eax_at(t) {
            Some(eax) => self.track_base(&eax),
            None => self.base_frame,
        }
    }
}

/// How far the track carries the robot's base over a move to `ext`, in the base frame
/// (mm): zero without a moving track.
pub(super) fn track_travel(robot: &super::robot::RobotState, ext: &ExternalMove) -> nalgebra::Vector3<f64> {
    match robot.external.track() {
        Some((axis, dir)) => robot.in_base(dir * (ext.to[axis] - ext.from[axis])),
        None => nalgebra::Vector3::zeros(),
    }
}

/// How much a move's programmed TCP speed is scaled so that the TCP keeps it in the
/// world while the track moves the robot's base: the planner times the path relative to
/// the base, which is longer or shorter than the world path by the track's travel. A
/// circle needs no scale: the planner keeps it in the world (`MotionSettings::base_travel`).
// uncertain: the TCP's acceleration is then applied along the base-relative path.
pub(super) fn track_speed_scale(
    robot: &super::robot::RobotState,
    target: &rapid_motion::plan::Target,
    chain: &rapid_motion::frames::FrameChain,
    ext: &ExternalMove,
) -> Result<f64, rapid_vm::ext::RapidError> {
    use rapid_motion::plan::Target;
    use rapid_motion::Kinematics as _;
    let Some((axis, dir)) = robot.external.track() else { return Ok(1.0) };
    // In the base frame, as the targets are.
    let shift = robot.in_base(dir * (ext.to[axis] - ext.from[axis]));
    if shift.norm() < 1e-9 {
        return Ok(1.0);
    }
    let to = match target {
        Target::Joints(_) => return Ok(1.0),
        Target::Linear(_) | Target::Circular { .. } if chain.stationary_tool => {
            return Err(rapid_vm::ext::RapidError::fatal("a stationary tool on a moving track is not supported yet"))
        }
        Target::Circular { .. } => return Ok(1.0),
        Target::Linear(to) => to.translation.vector,
    };
    let from = (robot.kin.forward(&robot.end_joints()) * chain.tframe).translation.vector;
    Ok(relative_over_world(from, to, shift))
}

/// The scale of a linear move's TCP speed from `from` to `to` (base frame, mm) while the
/// track carries the base by `shift`: the base-relative path's length over the world's.
pub(super) fn relative_over_world(
    from: nalgebra::Vector3<f64>,
    to: nalgebra::Vector3<f64>,
    shift: nalgebra::Vector3<f64>,
) -> f64 {
    let (relative, world) = ((to - from).norm(), (to - from + shift).norm());
    match (relative > 1e-6, world > 1e-6) {
        // The TCP stands in the world: the track's pace alone sets the time.
        (true, false) => 1e6,
        (true, true) => relative / world,
        _ => 1.0,
    }
}
