//! The frame chain of a robtarget (motion.md §3.6) on plain poses: world ← base ←
//! flange (`tool0`) ← tool, and world ← user frame ← object frame ← program
//! displacement ← target; with the tool held by the robot or stationary (the robot
//! then holds the work object). Also the pose arithmetic of Offs, RelTool and PDispOn.
//!
//! These are the computations behind MoveJ/MoveL targets, CalcJointT, CalcRobT,
//! CRobT and CPos; the VM turns its tooldata/wobjdata/progdisp values into a
//! [`FrameChain`] and its robtargets into poses.
//!
//! ```
//! use rapid_motion::pose::{pose, trans};
//! use rapid_motion::{find_model, ConfMatch, FrameChain, Kinematics};
//!
//! let kin = find_model("ROB1_120_0.58").unwrap().kinematics();
//! let chain = FrameChain { tframe: pose([0.0, 0.0, 100.0], [1.0, 0.0, 0.0, 0.0]), ..FrameChain::default() };
//! let target = pose([300.0, 50.0, 300.0], [0.0, 0.0, 1.0, 0.0]); // robtarget trans, rot
//! let current = [0.0; 6]; // CJointT
//! let goal = chain.joints_for(&kin, &target, &[0, 0, 0, 0], &current, ConfMatch::Compliant).unwrap();
//! let (back, conf) = chain.robtarget_of(&kin, &goal); // CalcRobT
//! assert!(trans(&back).iter().zip([300.0, 50.0, 300.0]).all(|(a, b)| (a - b).abs() < 1e-6));
//! assert_eq!(conf[3], 0);
//! let _nearest = kin.inverse_near(&chain.flange_goal(&target), &current); // ConfJ\Off
//! ```

use nalgebra::{Translation3, UnitQuaternion, Vector3};

use crate::confdata::{confdata_of, inverse_conf, ConfData, ConfMatch};
use crate::kinematics::Opw;
use crate::{Joints, Kinematics, MotionError, Pose};

/// The frames one move or one read-back is computed in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameChain {
    /// The robot's base frame in the world frame.
    pub base: Pose,
    /// `tooldata.tframe`: the TCP in the flange frame for a robot-held tool; the TCP in
    /// the world frame for a stationary tool.
    pub tframe: Pose,
    /// `wobjdata.uframe`: the user frame in the world frame for a fixed work object; in
    /// the flange frame for a work object the robot holds.
    pub uframe: Pose,
    /// `wobjdata.oframe`: the object frame in the user frame.
    pub oframe: Pose,
    /// The active program displacement (`C_PROGDISP.pdisp`), in the object frame.
    pub pdisp: Pose,
    /// `tool.robhold` FALSE with `wobj.robhold` TRUE: the robot carries the work object
    /// past a tool fixed in the room.
    pub stationary_tool: bool,
}

impl Default for FrameChain {
    /// `tool0`, `wobj0`, no displacement, base at the world origin.
    fn default() -> FrameChain {
        let id = Pose::identity();
        FrameChain { base: id, tframe: id, uframe: id, oframe: id, pdisp: id, stationary_tool: false }
    }
}

impl FrameChain {
    /// The flange pose in the base frame that puts the TCP on a robtarget's
    /// `[trans, rot]` (given as a pose in the displaced object frame): what inverse
    /// kinematics is asked for.
    pub fn flange_goal(&self, target: &Pose) -> Pose {
        let displaced = self.uframe * self.oframe * self.pdisp;
        let flange_world = if self.stationary_tool {
            // The robot-held object frame must carry the target onto the fixed TCP:
            // flange · object · target = tframe.
            self.tframe * target.inverse() * displaced.inverse()
        } else {
            displaced * target * self.tframe.inverse()
        };
        self.base.inverse() * flange_world
    }

    /// The robtarget pose (TCP in the displaced object frame) of a flange pose in the
    /// base frame: the inverse of [`FrameChain::flange_goal`], as CRobT, CPos and
    /// CalcRobT report it.
    // uncertain: CRobT/CPos/CalcRobT are taken to report in the displaced frame, so
    // moving to their result with the same PDisp active goes nowhere (motion.md §3.6).
    pub fn target_of(&self, flange: &Pose) -> Pose {
        let displaced = self.uframe * self.oframe * self.pdisp;
        let flange_world = self.base * flange;
        if self.stationary_tool {
            (flange_world * displaced).inverse() * self.tframe
        } else {
            displaced.inverse() * flange_world * self.tframe
        }
    }

    /// The TCP in the world frame for a flange pose in the base frame.
    pub fn tcp_in_world(&self, flange: &Pose) -> Pose {
        if self.stationary_tool {
            self.tframe
        } else {
            self.base * flange * self.tframe
        }
    }

    /// The TCP in the (undisplaced) object frame for a flange pose in the base frame.
    pub fn tcp_in_object(&self, flange: &Pose) -> Pose {
        self.pdisp * self.target_of(flange)
    }

    /// CalcRobT: the robtarget pose and configuration of a joint set.
    pub fn robtarget_of(&self, kin: &Opw, joints: &Joints) -> (Pose, ConfData) {
        (self.target_of(&kin.forward(joints)), confdata_of(kin, joints))
    }

    /// CalcJointT and the goal of a MoveJ/MoveL with ConfJ\On: the joints that put the
    /// TCP on the robtarget pose with the programmed configuration.
    pub fn joints_for(
        &self,
        kin: &Opw,
        target: &Pose,
        conf: &ConfData,
        seed: &Joints,
        mode: ConfMatch,
    ) -> Result<Joints, MotionError> {
        inverse_conf(kin, &self.flange_goal(target), conf, seed, mode)
    }
}

/// `Offs(p, dx, dy, dz)`: the point moved by (dx, dy, dz) mm along the axes of the
/// frame it is given in; the orientation is kept.
pub fn offs(p: &Pose, dx: f64, dy: f64, dz: f64) -> Pose {
    let mut res = *p;
    res.translation.vector += Vector3::new(dx, dy, dz);
    res
}

/// `RelTool(p, dx, dy, dz \Rx \Ry \Rz)`: the point moved by (dx, dy, dz) mm along the
/// tool's own axes at `p`, then turned about the tool's x, the new y and the new z
/// (degrees).
// uncertain: the order x, then y, then z of several rotations is from memory of the
// manual (motion.md §3.5).
pub fn rel_tool(p: &Pose, dx: f64, dy: f64, dz: f64, rx: f64, ry: f64, rz: f64) -> Pose {
    let turn = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), rx.to_radians())
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), ry.to_radians())
        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rz.to_radians());
    p * Pose::from_parts(Translation3::new(dx, dy, dz), turn)
}

/// `PDispOn [\Rot] ProgPoint`: the displacement that carries the programmed point onto
/// the actual one (both in the undisplaced object frame); translation only without
/// `\Rot`.
// uncertain: with \Rot the displacement is taken as actual · prog⁻¹ (the frame that
// maps the programmed pose onto the actual pose).
pub fn pdisp_from(prog_point: &Pose, actual: &Pose, with_rotation: bool) -> Pose {
    if with_rotation {
        return actual * prog_point.inverse();
    }
    Pose::from_parts(
        Translation3::from(actual.translation.vector - prog_point.translation.vector),
        UnitQuaternion::identity(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pose::{orient, pose, trans};

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-9)
    }

    #[test]
    fn offs_moves_in_the_given_frame() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let p = pose([100.0, 0.0, 50.0], [h, 0.0, h, 0.0]);
        let q = offs(&p, 10.0, 20.0, -5.0);
        assert!(close(trans(&q), [110.0, 20.0, 45.0]));
        assert_eq!(orient(&q), orient(&p));
    }

    #[test]
    fn rel_tool_moves_along_the_tool() {
        // A tool turned 90° about y: its z axis is the world's x axis, its x the world's −z.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let p = pose([100.0, 0.0, 50.0], [h, 0.0, h, 0.0]);
        let q = rel_tool(&p, 0.0, 0.0, 10.0, 0.0, 0.0, 0.0);
        assert!(close(trans(&q), [110.0, 0.0, 50.0]));
        let q = rel_tool(&p, 10.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        assert!(close(trans(&q), [100.0, 0.0, 40.0]));
        // Turning 90° more about the tool's y points its z down the world's −z:
        // 180° about y is [0, 0, 1, 0].
        let q = rel_tool(&p, 0.0, 0.0, 0.0, 0.0, 90.0, 0.0);
        let o = orient(&q);
        assert!(o[0].abs() < 1e-9 && (o[2].abs() - 1.0).abs() < 1e-9);
        // Rz after Rx: x by 90° takes tool z to −y; then z (the new z) by 90° turns about it.
        let id = Pose::identity();
        let q = rel_tool(&id, 0.0, 0.0, 0.0, 90.0, 0.0, 90.0);
        let x_axis = q.rotation * Vector3::x();
        assert!((x_axis - Vector3::new(0.0, 0.0, 1.0)).norm() < 1e-9);
    }

    #[test]
    fn robot_held_tool_chain_round_trips() {
        let chain = FrameChain {
            base: pose([0.0, 0.0, 100.0], [1.0, 0.0, 0.0, 0.0]),
            tframe: pose([0.0, 0.0, 200.0], [1.0, 0.0, 0.0, 0.0]),
            uframe: pose([500.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
            oframe: Pose::identity(),
            pdisp: pose([0.0, 10.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
            stationary_tool: false,
        };
        // Target straight down (180° about y) at [0, 0, 0] in the object: the TCP sits at
        // world (500, 10, 0); the flange 200 mm above it, i.e. at z 200 world, 100 in base.
        let target = pose([0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]);
        let goal = chain.flange_goal(&target);
        assert!(close(trans(&goal), [500.0, 10.0, 100.0]));
        assert!(close(trans(&chain.target_of(&goal)), [0.0, 0.0, 0.0]));
        assert!(close(trans(&chain.tcp_in_world(&goal)), [500.0, 10.0, 0.0]));
        assert!(close(trans(&chain.tcp_in_object(&goal)), [0.0, 10.0, 0.0]));
    }

    #[test]
    fn stationary_tool_chain_round_trips() {
        // A fixed TCP at world (800, 0, 300) pointing up (identity); the robot holds a
        // part whose object frame is 100 mm out along the flange's z.
        let chain = FrameChain {
            tframe: pose([800.0, 0.0, 300.0], [1.0, 0.0, 0.0, 0.0]),
            uframe: pose([0.0, 0.0, 100.0], [1.0, 0.0, 0.0, 0.0]),
            stationary_tool: true,
            ..FrameChain::default()
        };
        // The TCP at the object's origin, same orientation: flange · (0,0,100) = TCP, so
        // the flange is at (800, 0, 200).
        let goal = chain.flange_goal(&Pose::identity());
        assert!(close(trans(&goal), [800.0, 0.0, 200.0]));
        // The TCP 20 mm along the object's x: the object (and flange) sit 20 mm back.
        let goal = chain.flange_goal(&pose([20.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]));
        assert!(close(trans(&goal), [780.0, 0.0, 200.0]));
        assert!(close(trans(&chain.target_of(&goal)), [20.0, 0.0, 0.0]));
        assert!(close(trans(&chain.tcp_in_world(&goal)), [800.0, 0.0, 300.0]));
    }

    #[test]
    fn pdisp_on_translation_and_rotation() {
        let prog = pose([100.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]);
        let actual = pose([110.0, 5.0, 0.0], [0.0, 0.0, 0.0, 1.0]);
        let d = pdisp_from(&prog, &actual, false);
        assert!(close(trans(&d), [10.0, 5.0, 0.0]));
        assert_eq!(orient(&d), [1.0, 0.0, 0.0, 0.0]);
        let d = pdisp_from(&prog, &actual, true);
        assert!(close(trans(&(d * prog)), [110.0, 5.0, 0.0]));
    }
}
