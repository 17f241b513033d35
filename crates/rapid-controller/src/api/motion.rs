//! Where a robot's TCP is, for front ends (RWS's `/rw/motionsystem/.../robtarget`):
//! the flange the motion system reports now, carried through the frame chain of a
//! tool and a work object the robot's task declares (RAPID's `tooldata` and
//! `wobjdata`, read as the task holds them, not as text), shown in the base frame,
//! the world or the work object's object frame.
//!
//! The chain is the VM's own [`FrameChain`] (base, tframe, uframe, oframe), so the
//! frames mean here what they mean to CRobT. What CRobT can do and this cannot yet is
//! refused as not supported: a stationary tool, a work object the robot holds or a
//! unit moves. The program displacement is not applied (RWS reports the TCP in the
//! work object; PDispOn is a program's own business).

use rapid_motion::frames::FrameChain;
use rapid_motion::pose::{orient, pose, trans};
use rapid_motion::Pose;
use rapid_robot::RobotResources;
use rapid_vm::value::Value;

use super::{ApiError, Session};

/// The frame a TCP is told in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coordinate {
    /// The robot's base frame.
    Base,
    /// The world frame.
    World,
    /// The work object's object frame (`uframe` then `oframe`).
    Wobj,
}

/// A robot's TCP as a robtarget shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct TcpPose {
    /// x, y, z, mm.
    pub trans: [f64; 3],
    /// q1..q4, scalar first.
    pub orient: [f64; 4],
    /// cf1, cf4, cf6, cfx.
    pub conf: [i32; 4],
    /// External axes a..f (9E9 where the unit has none).
    pub extax: [f64; 6],
}

impl Session {
    /// The TCP of `tool` (a tooldata of the robot's task; `tool0` is the flange) of
    /// robot `unit` (0 is ROB_1, as [`Session::mechunits`] lists them), in
    /// `coordinate` (`wobj`, a wobjdata of the task, for [`Coordinate::Wobj`]).
    pub fn tcp_pose(
        &mut self,
        unit: usize,
        tool: &str,
        wobj: &str,
        coordinate: Coordinate,
    ) -> Result<TcpPose, ApiError> {
        let units = self.mechunits();
        let u = units.get(unit).ok_or_else(|| ApiError::NotFound(format!("no mechanical unit ROB_{}", unit + 1)))?;
        let task = u.task.clone();
        let mut chain = FrameChain { base: pose(u.base_trans, u.base_orient), ..FrameChain::default() };
        chain.tframe = self.tool_frame(&task, tool)?;
        if coordinate == Coordinate::Wobj {
            (chain.uframe, chain.oframe) = self.object_frames(&task, wobj)?;
        }
        let flange = pose(u.trans, u.orient);
        let shown = match coordinate {
            Coordinate::Base => flange * chain.tframe,
            Coordinate::World => chain.tcp_in_world(&flange),
            Coordinate::Wobj => chain.tcp_in_object(&flange),
        };
        Ok(TcpPose { trans: trans(&shown), orient: orient(&shown), conf: u.conf, extax: u.extax })
    }

    /// A robot-held tool's frame on the flange (`tframe`).
    fn tool_frame(&mut self, task: &str, tool: &str) -> Result<Pose, ApiError> {
        if tool.eq_ignore_ascii_case("tool0") {
            return Ok(Pose::identity());
        }
        let fields = self.record_of(task, tool, "tooldata", 3)?;
        if !matches!(fields[0], Value::Bool(true)) {
            return Err(ApiError::Unsupported(format!("robtarget with the stationary tool `{tool}`")));
        }
        frame_of(&fields[1], tool)
    }

    /// A fixed work object's user and object frames (the robot does not hold it and
    /// no unit moves it).
    fn object_frames(&mut self, task: &str, wobj: &str) -> Result<(Pose, Pose), ApiError> {
        if wobj.eq_ignore_ascii_case("wobj0") {
            return Ok((Pose::identity(), Pose::identity()));
        }
        let fields = self.record_of(task, wobj, "wobjdata", 5)?;
        if !matches!((&fields[0], &fields[1]), (Value::Bool(false), Value::Bool(true))) {
            return Err(ApiError::Unsupported(format!(
                "robtarget in the work object `{wobj}` (held by the robot or moved by a unit)"
            )));
        }
        Ok((frame_of(&fields[3], wobj)?, frame_of(&fields[4], wobj)?))
    }

    /// The fields of task `task`'s global datum `name`, a record of `arity` fields
    /// (a `tooldata`, a `wobjdata`), as the task holds it now.
    fn record_of(&mut self, task: &str, name: &str, type_name: &str, arity: usize) -> Result<Vec<Value>, ApiError> {
        let idx = self.task_index(task)?;
        let symbols = &self.controller.tasks[idx].loaded.vm.resources().symsearch;
        let datum = symbols
            .data()
            .iter()
            .find(|d| d.name.eq_ignore_ascii_case(name) && !d.local)
            .ok_or_else(|| ApiError::NotFound(format!("task {task} has no data `{name}`")))?;
        let global = datum.global;
        let value = self
            .controller
            .with_task(idx, &mut self.pendant, |vm, _| vm.global(global).cloned())
            .ok_or_else(|| ApiError::NotFound(format!("no value for data slot {global}")))?;
        match value {
            Value::Record(r) if r.fields.len() == arity => Ok(r.fields.clone()),
            _ => Err(ApiError::BadLiteral(format!("`{name}` is no {type_name}"))),
        }
    }
}

/// A `pose` value `[[x, y, z], [q1, q2, q3, q4]]` as a frame (its quaternion
/// normalised, as the motion system takes it).
fn frame_of(value: &Value, name: &str) -> Result<Pose, ApiError> {
    let bad = || ApiError::BadLiteral(format!("`{name}`: no pose, or an orientation that is not normalised"));
    let Value::Record(p) = value else { return Err(bad()) };
    let [Value::Record(t), Value::Record(q)] = p.fields.as_slice() else { return Err(bad()) };
    let numbers = |r: &rapid_vm::value::Record| -> Option<Vec<f64>> {
        r.fields
            .iter()
            .map(|v| match v {
                Value::Num(n) => Some(f64::from(*n)),
                Value::Dnum(n) => Some(*n),
                _ => None,
            })
            .collect()
    };
    match (numbers(t).as_deref(), numbers(q).as_deref()) {
        (Some(&[x, y, z]), Some(&[q1, q2, q3, q4])) => {
            rapid_motion::pose::checked_pose([x, y, z], [q1, q2, q3, q4]).ok_or_else(bad)
        }
        _ => Err(bad()),
    }
}

/// A robot arm drawn from its kinematic model, in the world frame (mm): the points a
/// viewer joins with links, and the TCP of the tool the last move used.
#[derive(Debug, Clone, PartialEq)]
pub struct ArmView {
    /// The task that moves it.
    pub task: String,
    /// Axes 1..6, degrees.
    pub joints: [f64; 6],
    /// Base, top of the base column, axis 2, axis 3, wrist centre, flange.
    pub points: Vec<[f64; 3]>,
    /// The active tool's TCP.
    pub tcp: [f64; 3],
}

impl Session {
    /// Every robot's arm as its OPW model places its axes now (ROB_1 first), for a
    /// viewer; the links between the points are the model's, not the robot's shape.
    pub fn arms(&mut self) -> Vec<ArmView> {
        use rapid_motion::Kinematics;
        let time = self.controller.time;
        let mut arms = Vec::new();
        for task in &mut self.controller.tasks {
            if !task.spec.robot {
                continue;
            }
            let robot = task.loaded.vm.resources_mut().robot_mut();
            let joints = robot.joints_at(time);
            let base = robot.track_base_at(time);
            let p = *robot.kin.params();
            let [q1, q2, ..] = joints.map(f64::to_radians);
            let (s1, c1) = q1.sin_cos();
            // A point of the arm's plane (reach x along the arm, height z) turned by axis 1.
            let turned = |x: f64, z: f64| [x * c1 - p.b * s1, x * s1 + p.b * c1, z];
            let flange = robot.kin.forward(&joints);
            let wrist = robot.kin.wrist_centre(&joints);
            let tcp = FrameChain { base, ..robot.active }.tcp_in_world(&flange);
            let local = [
                [0.0, 0.0, 0.0],
                [0.0, 0.0, p.c1],
                turned(p.a1, p.c1),
                turned(p.a1 + p.c2 * q2.sin(), p.c1 + p.c2 * q2.cos()),
                [wrist.x, wrist.y, wrist.z],
                trans(&flange),
            ];
            let world = |v: [f64; 3]| trans(&(base * pose(v, [1.0, 0.0, 0.0, 0.0])));
            arms.push(ArmView {
                task: task.spec.name.clone(),
                joints,
                points: local.into_iter().map(world).collect(),
                tcp: trans(&tcp),
            });
        }
        arms
    }
}
