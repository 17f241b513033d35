//! Path correction (the `\Corr` argument of the move instructions): an offset, given
//! in the path coordinate system, laid on top of a planned sample. The planner never
//! sees it; whoever samples a corrected move asks for the shifted robot here.
//!
//! The path coordinate system at a point of the path: x along the direction the path
//! goes, z the tool's z axis made square to x, y = z × x (a right-handed frame).
// uncertain: ABB's manual says only that the offsets are "in the path coordinate
// system"; the axes above are our reading of it (x the travel direction, z the tool
// direction), as sensor tracking uses them (y sideways, z height).

use nalgebra::{Matrix3, Rotation3, Translation3, Vector3};

use super::sample::{PlannedMove, Sample};
use super::Mount;
use crate::{Kinematics, MotionError, Pose};

/// The time either side of a sample the path direction is measured over, s.
const DIRECTION_STEP: f64 = 0.002;

/// The path coordinate system for a path going in `direction` with a tool whose z
/// axis is `tool_z` (both in one frame). When the path does not move (a pure
/// reorientation) or goes along the tool's z axis, the tool's own axes stand in for
/// what is missing.
pub fn path_frame(direction: &Vector3<f64>, tool: &Rotation3<f64>) -> Rotation3<f64> {
    let tool_z = tool * Vector3::z();
    let Some(x) = direction.try_normalize(1e-9) else { return *tool };
    let square = tool_z - x * x.dot(&tool_z);
    let z = square.try_normalize(1e-9).unwrap_or_else(|| {
        // The tool points along the path: its x axis, made square to the path, is z.
        let tool_x = tool * Vector3::x();
        (tool_x - x * x.dot(&tool_x)).try_normalize(1e-9).unwrap_or_else(|| x.cross(&Vector3::y()).normalize())
    });
    let y = z.cross(&x);
    Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[x, y, z]))
}

impl PlannedMove {
    /// How the move's path relates to the flange.
    pub fn mount(&self) -> Mount {
        self.mount
    }

    /// The path pose (see [`Mount`]) at `sample`.
    fn path_pose_of(&self, sample: &Sample) -> Pose {
        self.mount.path_pose(&sample.flange)
    }

    /// The direction the path goes at time `t`: a central difference over a few ms,
    /// else the move's chord (at a standstill); None when the path pose does not move
    /// at all (a pure reorientation, a pause).
    fn path_direction<K: Kinematics + ?Sized>(&self, kin: &K, t: f64) -> Option<Vector3<f64>> {
        let at = |t: f64| self.path_pose_of(&self.sample(kin, t)).translation.vector;
        let local = at(t + DIRECTION_STEP) - at(t - DIRECTION_STEP);
        if local.norm() > 1e-6 {
            return Some(local);
        }
        let chord = at(self.end) - at(self.start);
        (chord.norm() > 1e-6).then_some(chord)
    }

    /// The path coordinate system at time `t` of the move (in the frame of the path
    /// pose: the robot base, or a held work object's for a stationary tool); None
    /// when the path does not move (see [`PlannedMove::path_frame_at`]).
    pub fn travel_frame_at<K: Kinematics + ?Sized>(&self, kin: &K, t: f64) -> Option<Rotation3<f64>> {
        let direction = self.path_direction(kin, t)?;
        let path = self.path_pose_of(&self.sample(kin, t));
        Some(path_frame(&direction, &path.rotation.to_rotation_matrix()))
    }

    /// The path coordinate system at time `t`, or where the path does not move the
    /// tool's own frame there.
    pub fn path_frame_at<K: Kinematics + ?Sized>(&self, kin: &K, t: f64) -> Rotation3<f64> {
        self.travel_frame_at(kin, t)
            .unwrap_or_else(|| self.path_pose_of(&self.sample(kin, t)).rotation.to_rotation_matrix())
    }

    /// The robot at `sample` (a sample of this move) with the path shifted by `offset`
    /// (mm, in the path coordinate system there). See [`PlannedMove::shifted`].
    pub fn corrected<K: Kinematics + ?Sized>(
        &self,
        kin: &K,
        sample: &Sample,
        offset: &Vector3<f64>,
    ) -> Result<Sample, MotionError> {
        let frame = self.path_frame_at(kin, sample.time);
        self.shifted(kin, sample, &(frame * offset))
    }

    /// The robot at `sample` with the path pose moved by `shift` (mm, in the frame of
    /// the path pose): the flange that puts it there and the axis values nearest the
    /// planned ones. The TCP speed stays the planned one. An error when no axis values
    /// reach it.
    pub fn shifted<K: Kinematics + ?Sized>(
        &self,
        kin: &K,
        sample: &Sample,
        shift: &Vector3<f64>,
    ) -> Result<Sample, MotionError> {
        if !shift.iter().all(|x| x.is_finite()) {
            return Err(MotionError::InvalidData("a path correction that is not a number"));
        }
        let shifted = Translation3::from(*shift) * self.path_pose_of(sample);
        let flange = self.mount.flange(&shifted);
        let joints = kin.inverse_near(&flange, &sample.joints)?;
        // The flange the axis values give (the solver's rounding, not the request).
        let flange = kin.forward(&joints);
        Ok(Sample { joints, tcp: self.mount.tcp(&flange), flange, ..*sample })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_path_frame_follows_the_travel_and_the_tool() {
        // Travel along +x with the tool pointing down (tool z = -z): path z is -z and
        // y = z × x = -y.
        let down = Rotation3::from_axis_angle(&Vector3::y_axis(), std::f64::consts::PI);
        let frame = path_frame(&Vector3::new(10.0, 0.0, 0.0), &down);
        let expect = |v: Vector3<f64>, w: Vector3<f64>| assert!((v - w).norm() < 1e-9, "{v} != {w}");
        expect(frame * Vector3::x(), Vector3::x());
        expect(frame * Vector3::y(), -Vector3::y());
        expect(frame * Vector3::z(), -Vector3::z());
        // A tool tilted towards the travel: z is made square to the path.
        let tilted = Rotation3::from_axis_angle(&Vector3::y_axis(), 0.75 * std::f64::consts::PI);
        let frame = path_frame(&Vector3::new(1.0, 0.0, 0.0), &tilted);
        expect(frame * Vector3::z(), -Vector3::z());
        // No travel: the tool's own frame.
        let frame = path_frame(&Vector3::zeros(), &down);
        expect(frame * Vector3::z(), -Vector3::z());
    }
}
