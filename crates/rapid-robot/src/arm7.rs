//! A robot with a 7th arm axis (the IRB 14000 YuMi's arms, `rapid_motion::kinematics::yumi`).
//!
//! RAPID carries axis 7 in `extax.eax_a`: a jointtarget's eax_a is the axis value
//! (MoveAbsJ moves it, CJointT reads it), a robtarget's eax_a is the arm angle (MoveJ,
//! MoveL and MoveC reach the target with that arm angle; CRobT reads it). The task
//! gives the planner axis 7 as the external axis eax_a (`ExternalUnits::arm7`): it moves
//! with the arm's other axes, its range is checked as an external axis's is (a value
//! outside it is joint 7's limit error), and it reads back as one. A robtarget move
//! finds axis 7 at the target from its arm angle before it is given
//! ([`target_axis7`]). The public record for all this is in `kinematics/yumi.rs`.

use crate::RobotResources;
use rapid_motion::external::{is_unused, Eax, ExternalAxis};
use rapid_motion::kinematics::yumi;
use rapid_motion::{Joints, Kinematics, MotionError, Pose};

use super::robot::RobotState;
use rapid_vm::ext::{Ctx, RapidError};

/// How fast axis 7 may accelerate at AccSet 100 %, °/s²: its top speed reached in the
/// planner's axis ramp time (0.15 s, `rapid_motion::plan::AccelLimits::nominal`).
const AXIS7_ACC: f64 = 180.0 / 0.15;

impl RobotState {
    /// Axis 7 of a 7-axis arm as the planner's external axis eax_a (logical axis 7),
    /// standing where the arm has it; `None` for other robots.
    pub(super) fn arm_axis7(&self) -> Option<ExternalAxis> {
        let arm = self.kin.seventh()?;
        let (min, max) = yumi::LIMITS[6];
        Some(ExternalAxis {
            logical: 7,
            linear: false,
            min,
            max,
            max_speed: yumi::SPEEDS[6],
            acc: AXIS7_ACC,
            start: arm.axis7,
            mount: Pose::identity(),
        })
    }

    /// The seven axes of a 7-axis arm at `joints` with the external axes at `eax` (axis
    /// 7 where the arm stands when they are not given).
    fn joints7(&self, joints: &Joints, eax: Option<&Eax>) -> Option<(yumi::Side, yumi::Joints7)> {
        let arm = self.kin.seventh()?;
        Some((arm.side, arm.joints7(joints, eax)))
    }

    /// The flange (base frame) and configuration for `joints` with the external axes at
    /// `eax`: [`RobotState::flange_of`] with a 7-axis arm's axis 7 from eax_a.
    pub fn flange_at(&self, joints: &Joints, eax: Option<&Eax>) -> (Pose, rapid_motion::confdata::ConfData) {
        match self.joints7(joints, eax) {
            Some((side, q)) => (yumi::forward(side, &q), yumi::confdata(&q)),
            None => self.flange_of(joints),
        }
    }

    /// A robtarget's `extax` as read back: a 7-axis arm's eax_a is its arm angle, not
    /// axis 7 (`extax` as the external axes read it otherwise).
    pub fn robtarget_extax(&self, joints: &Joints, eax: Option<&Eax>, mut extax: [f64; 6]) -> [f64; 6] {
        if let Some((side, q)) = self.joints7(joints, eax) {
            extax[0] = yumi::arm_angle(side, &q);
        }
        extax
    }

    /// Where axis 7 stands once every move given has run.
    fn end_axis7(&self) -> Option<f64> {
        let arm = self.kin.seventh()?;
        let q7 = self.planner.end_eax().map(|e| e[0]).filter(|q| !is_unused(*q));
        Some(q7.unwrap_or(arm.axis7))
    }
}

/// The seven axes that put a 7-axis arm's flange at `flange` (base frame) with arm angle
/// `angle` (a robtarget's eax_a; 9E9 keeps the angle the arm has at the end of its last
/// move), nearest where that move leaves it; `None` for other robots. Unreachable: the
/// controller's position-outside-reach error.
// uncertain: that 9E9 keeps the current arm angle; the public programs always give one.
// uncertain: our arm angle's zero and sense are our reading (`yumi::arm_angle`); the one
// public target with a matching MoveAbsJ has ABB's −173.7° where ours is 71.3°, so the
// elbow of a program written on a real YuMi may stand elsewhere here (the TCP does not).
pub(super) fn solve7(robot: &RobotState, flange: &Pose, angle: f64) -> Result<Option<yumi::Joints7>, MotionError> {
    let Some(arm) = robot.kin.seventh() else { return Ok(None) };
    let q = robot.end_joints();
    let q7 = robot.end_axis7().unwrap_or(arm.axis7);
    let seed = [q[0], q[1], q[2], q[3], q[4], q[5], q7];
    let angle = if is_unused(angle) { yumi::arm_angle(arm.side, &seed) } else { angle };
    yumi::inverse(arm.side, flange, angle, &seed).map(Some)
}

/// Before a robtarget move of a 7-axis arm: axis 7 at the target, from the target's arm
/// angle (`extax[0]`) and where the flange goes, kept for the move's external axes
/// (`external_target`). Returns the seven axes; `None` for other robots.
pub(super) fn target_axis7(
    ctx: &mut Ctx<'_>,
    flange: &Pose,
    extax: &[f64; 6],
) -> Result<Option<yumi::Joints7>, RapidError> {
    let found = solve7(ctx.resources.robot_mut(), flange, extax[0]).map_err(super::moves::motion_error)?;
    ctx.resources.robot_mut().next_axis7 = found.map(|q| q[6]);
    Ok(found)
}

/// The flange of a 7-axis arm's joints whose axis 7 is `q7` (a jointtarget's eax_a),
/// with its configuration and arm angle; `None` for other robots.
pub(super) fn flange_of_target(
    robot: &RobotState,
    joints: &Joints,
    q7: f64,
) -> Option<(Pose, rapid_motion::confdata::ConfData, f64)> {
    let (side, q) = robot.joints7(joints, Some(&[q7; 6]))?;
    Some((yumi::forward(side, &q), yumi::confdata(&q), yumi::arm_angle(side, &q)))
}

/// Whether the robot is a 7-axis arm.
pub(super) fn has_axis7(robot: &RobotState) -> bool {
    robot.kin.redundant()
}
