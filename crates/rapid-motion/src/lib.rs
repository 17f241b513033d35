//! rapid-motion: the motion computation of the virtual controller, with no controller
//! state and no IO: robot models and their kinematics, frames and poses in RAPID's
//! units, and (later) path planning, corner paths and timing.
//!
//! Units at every public boundary are RAPID's: millimetres, degrees, quaternions
//! with the scalar first (`orient = [q1, q2, q3, q4]`). Conversions to whatever a
//! solver uses internally happen inside the module that calls it.

pub mod calib;
pub mod confdata;
pub mod dynamics;
pub mod external;
pub mod frames;
pub mod kinematics;
pub mod plan;
pub mod pose;
pub mod robots;

pub use confdata::{confdata_of, inverse_conf, inverse_nearest, ConfData, ConfMatch};
pub use frames::{offs, pdisp_from, rel_tool, FrameChain};
pub use kinematics::{Opw, OpwParams};
pub use pose::{Joints, Pose};
pub use robots::{default_model, find_model, models, RobotModel};

/// Why a motion computation has no answer. Each maps to the controller's error when
/// the VM reports it (ERR_ROBLIMIT and friends).
#[derive(Debug, Clone, PartialEq)]
pub enum MotionError {
    /// The pose is outside the robot's reach (no inverse-kinematics solution).
    OutOfReach,
    /// Solutions exist, but none within the joint limits; the axis (1-based) that
    /// limits the closest one.
    JointLimit { axis: usize },
    /// No solution with the asked configuration (confdata), though others exist.
    Configuration,
    /// The path passes (too close to) a singularity the move cannot cross.
    Singularity,
    /// MoveC's start, circle point and end point are coincident or on one line.
    DegenerateCircle,
    /// The motion data cannot be moved with (a zero speed for a motion that
    /// needs it, a non-finite value); what is wrong.
    InvalidData(&'static str),
}

impl std::fmt::Display for MotionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MotionError::OutOfReach => write!(f, "position outside reach"),
            MotionError::JointLimit { axis } => write!(f, "joint {axis} out of range"),
            MotionError::Configuration => write!(f, "the configuration asked for cannot be reached"),
            MotionError::Singularity => write!(f, "the path passes a singularity"),
            MotionError::DegenerateCircle => write!(f, "the circle points do not define a circle"),
            MotionError::InvalidData(what) => write!(f, "invalid motion data: {what}"),
        }
    }
}

impl std::error::Error for MotionError {}

/// A 6-axis arm's kinematics, in RAPID units. `forward` gives the flange (`tool0`)
/// in the robot's base frame; `inverse` every joint solution within the joint limits
/// for a flange pose, in no particular order.
pub trait Kinematics {
    fn forward(&self, joints: &Joints) -> Pose;
    fn inverse(&self, flange: &Pose) -> Vec<Joints>;
    /// Lower and upper limit of each axis, degrees.
    fn limits(&self) -> [(f64, f64); 6];
    /// Maximum speed of each axis, degrees per second.
    fn max_speeds(&self) -> [f64; 6];

    /// The solution closest to `seed` (largest single-axis move smallest), or why
    /// there is none.
    fn inverse_near(&self, flange: &Pose, seed: &Joints) -> Result<Joints, MotionError> {
        let distance = |j: &Joints| j.iter().zip(seed).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        self.inverse(flange)
            .into_iter()
            .min_by(|a, b| distance(a).total_cmp(&distance(b)))
            .ok_or(MotionError::OutOfReach)
    }

    /// [`Kinematics::forward`] with the external axes at `eax`: a 7-axis arm (the
    /// YuMi's) carries its axis 7 in `eax_a`; other arms ignore them.
    fn forward_at(&self, joints: &Joints, _eax: &external::Eax) -> Pose {
        self.forward(joints)
    }

    /// [`Kinematics::inverse_near`] with the external axes at `eax` (a 7-axis arm's
    /// axis 7 held at `eax_a`).
    fn inverse_near_at(&self, flange: &Pose, seed: &Joints, _eax: &external::Eax) -> Result<Joints, MotionError> {
        self.inverse_near(flange, seed)
    }

    /// Whether the arm has a 7th axis in `eax_a`: the planner then gives every
    /// kinematics call along a path the external axes there.
    fn redundant(&self) -> bool {
        false
    }
}
