//! Where the robot is (§1.8): CJointT, CRobT, CPos, and the kinematics functions
//! CalcJointT and CalcRobT. Read-backs sample the planned motion at the controller's
//! time; without `\Tool`/`\WObj` they use the last move's tool and work object.

use crate::RobotResources;
use rapid_motion::confdata::ConfMatch;
use rapid_motion::frames::FrameChain;
use rapid_motion::{Kinematics, MotionError};

use super::data;
use rapid_tasks::TaskingAccess;
use rapid_vm::ext::{present, Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// Another task's robot as the controller reports it ([`RobotReport`]), and whether
/// that task moves a robot (a positioner's task moves its external axes only).
struct OtherRobot {
    report: RobotReport,
    tcp: bool,
}

/// Another task's robot as that task reports it to the controller (the payload of
/// `Reply::Extension` answering `Request::Robot`): its axes, active frames and
/// external axes, and where its flange is in its base frame with its configuration
/// (by its own kinematics: the robots of a system may be of different models).
#[derive(Debug, Clone, PartialEq)]
struct RobotReport {
    joints: rapid_motion::Joints,
    frames: FrameChain,
    /// Its external axes (`extjoint`, 9E9 where it has none).
    extax: [f64; 6],
    /// `extax` as CRobT reads it (a 7-axis arm's eax_a: its arm angle).
    robtarget_extax: [f64; 6],
    flange: rapid_motion::Pose,
    conf: rapid_motion::confdata::ConfData,
}

/// The controller's reply to another task's `Request::Robot` about the robot of the
/// task whose resources these are, at `time`.
pub fn robot_reply(resources: &mut rapid_vm::ext::Resources, time: f64) -> rapid_vm::ext::Reply {
    let robot = resources.robot_mut();
    // Its frames with its base where it stands in the world now (MOC.cfg's base
    // frame, on a track where the track has it).
    let mut frames = robot.active;
    frames.base = robot.track_base_at(time);
    let joints = robot.joints_at(time);
    // As the robot's own CRobT reads it: a 7-axis arm's flange with axis 7 where it
    // stands, its eax_a the arm angle.
    let eax = robot.eax_at(time);
    let (flange, conf) = robot.flange_at(&joints, eax.as_ref());
    let extax = robot.extax_read(time);
    let robtarget_extax = robot.robtarget_extax(&joints, eax.as_ref(), extax);
    let report = RobotReport { joints, frames, extax, robtarget_extax, flange, conf };
    rapid_vm::ext::Reply::Extension(rapid_vm::ext::ExtensionReply(std::rc::Rc::new(report)))
}

/// The robot a read-back is about: this task's (None), or another task's
/// (`Some(None)`: wait for the reply).
fn robot_of(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Option<OtherRobot>>, RapidError> {
    use rapid_vm::ext::{ask, other_task, Reply, Request};
    let Some(task) = other_task(ctx, args, 0)?.or_else(|| linked_motion_task(ctx)) else { return Ok(None) };
    Ok(Some(match ask(ctx, Request::Robot { task }) {
        Some(Reply::Extension(reply)) => {
            let Some(report) = reply.0.downcast_ref::<RobotReport>().cloned() else {
                return Err(RapidError::fatal("the task has no robot"));
            };
            let tcp = ctx.resources.tasking().shared.tasks.get(task).is_none_or(|t| t.robot);
            Some(OtherRobot { report, tcp })
        }
        Some(_) => return Err(RapidError::fatal("the task has no robot")),
        None => None,
    }))
}

/// A task that is no motion task reads the robot of the motion task whose mechanical
/// unit group it uses (SYS.cfg `-UseMechanicalUnitGroup`), as if named by `\TaskName`.
fn linked_motion_task(ctx: &Ctx<'_>) -> Option<usize> {
    let name = rapid_tasks::my_task(ctx)?.robot_of.as_deref()?;
    ctx.resources.tasking().shared.tasks.iter().position(|t| t.name.eq_ignore_ascii_case(name))
}

/// The frames a read-back uses: the given tool and work object, else the active ones.
fn read_frames(ctx: &Ctx<'_>, tool: Option<&Value>, wobj: Option<&Value>) -> Result<FrameChain, RapidError> {
    let active = ctx.resources.robot().active;
    let pdisp = ctx.resources.motion().settings.pdisp;
    let tool_value = match tool.filter(|t| present(Some(t))) {
        Some(t) => Some(ctx.value(t)?),
        None => None,
    };
    let wobj_value = match wobj.filter(|w| present(Some(w))) {
        Some(w) => Some(ctx.value(w)?),
        None => None,
    };
    // On a track the robot's base is where the track is now.
    let base = ctx.resources.robot().track_base_at(ctx.time);
    match (tool_value, wobj_value) {
        (None, None) => {
            // A work object the robot follows is where it is now.
            let uframe = super::tracking::active_uframe_at(ctx.resources.robot(), ctx.time);
            Ok(FrameChain { pdisp, base, uframe, ..active })
        }
        (Some(tool), Some(wobj)) => data::chain(ctx, &tool, Some(&wobj), pdisp),
        (Some(tool), None) => {
            // The active work object, where it is now (CRobT and CPos; CalcRobT and
            // CalcJointT take wobj0 for an omitted \WObj: `target_frames`).
            // A stationary tool goes with a work object the robot holds, as in a move.
            if data::tool_held(ctx, &tool)? == active.stationary_tool {
                return Err(RapidError::fatal(
                    "the tool and the active work object cannot both be held (or both fixed): give \\WObj",
                ));
            }
            let mut chain = data::chain(ctx, &tool, None, pdisp)?;
            let uframe = super::tracking::active_uframe_at(ctx.resources.robot(), ctx.time);
            chain.uframe = uframe;
            chain.oframe = active.oframe;
            chain.stationary_tool = active.stationary_tool;
            Ok(chain)
        }
        (None, Some(wobj)) => {
            // uncertain: \WObj without \Tool reads with the active tool.
            let mut chain = data::chain(ctx, &tool0_like(ctx)?, Some(&wobj), pdisp)?;
            chain.tframe = active.tframe;
            Ok(chain)
        }
    }
}

/// The frames CalcJointT and CalcRobT compute with, for a target whose external axes
/// are `extax`: on a track, the base where the target's track value puts it; a work
/// object an external unit of this task carries, where the target's values put the
/// unit (those it gives; `current`, CalcJointT's `\UseCurWObjPos`: where the unit is
/// now); one another task's unit carries, where that unit is now. A unit that carries
/// the work object from where it is now must stand: ERR_WOBJ_MOVING.
// uncertain: that CalcJointT without \UseCurWObjPos takes the unit where the target's
// extax has it, and that ERR_WOBJ_MOVING is raised only when the unit's current position
// is used, are our reading of the function's arguments.
fn target_frames(
    ctx: &Ctx<'_>,
    tool: Option<&Value>,
    wobj: Option<&Value>,
    extax: &[f64; 6],
    current: bool,
) -> Result<FrameChain, RapidError> {
    use super::tracking::Carrier;
    let given = wobj.filter(|w| present(Some(w)));
    let mut chain = match (tool.filter(|t| present(Some(t))), given) {
        // An omitted \WObj is wobj0 here (CRobT and CPos take the active one), which a
        // stationary tool cannot go with: the manual asks for \WObj then.
        (Some(tool), None) => {
            let tool = ctx.value(tool)?;
            if !data::tool_held(ctx, &tool)? {
                return Err(RapidError::fatal(
                    "a stationary tool (robhold FALSE) needs \\WObj, the work object the robot holds",
                ));
            }
            data::chain(ctx, &tool, None, ctx.resources.motion().settings.pdisp)?
        }
        _ => read_frames(ctx, tool, wobj)?,
    };
    let robot = ctx.resources.robot();
    chain.base = robot.track_base(extax);
    let Some(wobj) = given else { return Ok(chain) };
    let now = ctx.time;
    let moving = |at: &dyn Fn(f64) -> Option<rapid_motion::external::Eax>| at(now) != at(now + MOVING_PROBE);
    match super::tracking::carrier_of(ctx, &ctx.value(wobj)?)? {
        Some(Carrier::Unit(u)) if !current => {
            let mover = super::tracking::unit_mover(robot, u)?;
            let mut at = robot.eax_at(now).unwrap_or_default();
            for (slot, value) in at.iter_mut().zip(extax) {
                if !rapid_motion::external::is_unused(*value) {
                    *slot = *value;
                }
            }
            chain.uframe = mover.user_frame(&robot.following.conveyors, &at);
        }
        Some(Carrier::Unit(_)) if moving(&|t| robot.eax_at(t)) => return Err(wobj_moving(ctx)),
        Some(Carrier::Foreign(f)) if moving(&|t| robot.foreign_eax_at(f, t)) => return Err(wobj_moving(ctx)),
        _ => {}
    }
    Ok(chain)
}

/// How far ahead (s) a unit's axes are looked at to see whether it moves now.
const MOVING_PROBE: f64 = 1e-3;

fn wobj_moving(ctx: &Ctx<'_>) -> RapidError {
    ctx.error(Err::WobjMoving, "the mechanical unit that carries the work object is moving")
}

/// A tool0-shaped value, to read a work object's frames with.
fn tool0_like(ctx: &Ctx<'_>) -> Result<Value, RapidError> {
    let name = "tool0";
    ctx.data_by_name
        .get(name)
        .and_then(|d| ctx.storage.globals.get(d.global).cloned())
        .ok_or_else(|| RapidError::fatal("the program has no tool0"))
}

rapid_vm::ext::layout! {
    static CROBT: CRobTArgs = "CRobT" { tool: "Tool", wobj: "WObj" }
    static CPOS: CPosArgs = "CPos" { tool: "Tool", wobj: "WObj" }
    static CALC_ROB_T: CalcRobTArgs = "CalcRobT" { target: "Joint_target", tool: "Tool", wobj: "WObj" }
    static CALC_JOINT_T: CalcJointTArgs = "CalcJointT" {
        use_cur: "UseCurWObjPos", target: "Rob_target", tool: "Tool", wobj: "WObj", error_number: "ErrorNumber",
    }
    static PDISP_ON: PDispOnArgs = "PDispOn" {
        rot: "Rot", exe_p: "ExeP", prog_point: "ProgPoint", tool: "Tool", wobj: "WObj",
    }
    static EOFFS_ON: EOffsOnArgs = "EOffsOn" { exe_p: "ExeP", prog_point: "ProgPoint" }
}

/// `CJointT([\TaskRef] | [\TaskName])`: the axis values now.
pub(crate) fn c_joint_t(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    super::tracking::refresh(ctx);
    let (joints, extax, tcp) = match robot_of(ctx, args)? {
        Some(Some(other)) => (other.report.joints, other.report.extax, other.tcp),
        Some(None) => return Ok(Some(data::jointtarget_value(ctx, &[0.0; 6])?)),
        None => {
            let now = ctx.time;
            let tcp = super::moves::moves_robot(ctx);
            (ctx.resources.robot_mut().joints_at(now), ctx.resources.robot_mut().extax_read(now), tcp)
        }
    };
    // A positioner's task has no robot axes: they read 9E9, as axes the system lacks.
    // uncertain: the controller's robax for such a task is not in our sources.
    let joints = if tcp { joints } else { [data::UNUSED_AXIS; 6] };
    Ok(Some(super::frame::with_extax(&data::jointtarget_value(ctx, &joints)?, &extax)))
}

/// CRobT and CPos need a TCP: a positioner's task (this one, or `other`) has none.
// uncertain: the controller's error for them in such a task is not in our sources;
// execution stops.
fn require_tcp(ctx: &Ctx<'_>, other: Option<&OtherRobot>, what: &str) -> Result<(), RapidError> {
    let tcp = other.map_or_else(|| super::moves::moves_robot(ctx), |o| o.tcp);
    if tcp {
        return Ok(());
    }
    let motion = rapid_tasks::my_task(ctx).is_none_or(|t| t.motion);
    Err(RapidError::fatal(if other.is_none() && !motion {
        format!(
            "{what}: the task is no motion task and uses no motion task's mechanical unit group \
             (-UseMechanicalUnitGroup): there is no robot to read"
        )
    } else {
        format!("{what}: the task moves no robot (a positioner's task): there is no TCP to read")
    }))
}

/// `CRobT([\TaskRef] | [\TaskName] [\Tool] [\WObj])`: the robtarget the robot is at.
pub(crate) fn c_rob_t(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    super::tracking::refresh(ctx);
    let other = robot_of(ctx, args)?;
    match &other {
        None => require_tcp(ctx, None, "CRobT")?,
        Some(Some(answer)) => require_tcp(ctx, Some(answer), "CRobT")?,
        // The other task has not answered yet.
        Some(None) => {}
    }
    let at = *CROBT;
    let mut chain = read_frames(ctx, args.get(at.tool), args.get(at.wobj))?;
    let now = ctx.time;
    let (flange, conf, extax) = match other {
        // The other task's active frames stand in for the arguments not given.
        Some(Some(other)) => {
            if !present(args.get(at.tool)) && !present(args.get(at.wobj)) {
                chain = other.report.frames;
            } else {
                // The given tool and work object on the other robot, which stands where
                // its base frame is.
                chain.base = other.report.frames.base;
            }
            (other.report.flange, other.report.conf, other.report.robtarget_extax)
        }
        Some(None) => return Ok(Some(data::robtarget_value(ctx, &nalgebra::Isometry3::identity(), [0; 4])?)),
        None => {
            let robot = ctx.resources.robot_mut();
            let joints = robot.joints_at(now);
            // A 7-axis arm's axis 7 is in the external axes; its eax_a reads the arm angle.
            let eax = robot.eax_at(now);
            let (flange, conf) = robot.flange_at(&joints, eax.as_ref());
            let extax = robot.extax_read(now);
            (flange, conf, robot.robtarget_extax(&joints, eax.as_ref(), extax))
        }
    };
    let pose = chain.target_of(&flange);
    Ok(Some(super::frame::with_extax(&data::robtarget_value(ctx, &pose, conf)?, &extax)))
}

/// `CPos([\Tool] [\WObj])`: the TCP's position now.
pub(crate) fn c_pos(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if linked_motion_task(ctx).is_some() {
        // The robot of the motion task whose unit group this task uses: CRobT's position.
        let (crobt, cpos) = (*CROBT, *CPOS);
        let arg = |i: usize| args.get(i).cloned().unwrap_or(Value::Absent);
        let mut call = vec![Value::Absent; crobt.tool.max(crobt.wobj) + 1];
        (call[crobt.tool], call[crobt.wobj]) = (arg(cpos.tool), arg(cpos.wobj));
        let target = c_rob_t(ctx, &call)?;
        return Ok(match target {
            Some(Value::Record(record)) => record.fields.first().cloned(),
            other => other,
        });
    }
    super::tracking::refresh(ctx);
    require_tcp(ctx, None, "CPos")?;
    let chain = read_frames(ctx, args.get(CPOS.tool), args.get(CPOS.wobj))?;
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    let joints = robot.joints_at(now);
    let pose = match robot.kin.redundant() {
        // A 7-axis arm: axis 7 where the external axes have it now.
        true => chain.target_of(&robot.flange_at(&joints, robot.eax_at(now).as_ref()).0),
        false => chain.target_of(&robot.kin.forward(&joints)),
    };
    Ok(Some(data::pos_value(ctx, &pose)?))
}

/// `CalcRobT(Joint_target, Tool [\WObj])`: the robtarget of axis values.
// The external axis values are carried over unchanged.
pub(crate) fn calc_rob_t(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *CALC_ROB_T;
    let target = ctx.value(&args[at.target])?;
    let joints = data::jointtarget(ctx, &target)?;
    let extax = data::target_extax(ctx, &target)?;
    let mut extax = extax;
    let chain = target_frames(ctx, args.get(at.tool), args.get(at.wobj), &extax, false)?;
    let (pose, conf) = match super::arm7::flange_of_target(ctx.resources.robot_mut(), &joints, extax[0]) {
        // A 7-axis arm: axis 7 from the jointtarget's eax_a, the robtarget's is the arm angle.
        Some((flange, conf, angle)) => {
            extax[0] = angle;
            (chain.target_of(&flange), conf)
        }
        None => chain.robtarget_of(&ctx.resources.robot_mut().kin, &joints),
    };
    Ok(Some(super::frame::with_extax(&data::robtarget_value(ctx, &pose, conf)?, &extax)))
}

/// `CalcJointT([\UseCurWObjPos] Rob_target, Tool [\WObj] [\ErrorNumber])`: the axis
/// values that reach a robtarget in its configuration. ERR_OUTSIDE_REACH when no
/// configuration reaches it, ERR_ROBLIMIT when an axis would leave its range or the
/// configuration cannot; with `\ErrorNumber` the number goes there instead and the
/// current axis values are returned.
// uncertain: what CalcJointT returns when it stores the error in \ErrorNumber.
// The external axis values are carried over unchanged.
pub(crate) fn calc_joint_t(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *CALC_JOINT_T;
    let target = ctx.value(&args[at.target])?;
    let (pose, conf) = data::robtarget(ctx, &target)?;
    let extax = data::target_extax(ctx, &target)?;
    let chain = target_frames(ctx, args.get(at.tool), args.get(at.wobj), &extax, present(args.get(at.use_cur)))?;
    let now = ctx.time;
    let seed = ctx.resources.robot_mut().joints_at(now);
    let mut extax = extax;
    let found = match super::arm7::solve7(ctx.resources.robot_mut(), &chain.flange_goal(&pose), extax[0]) {
        // A 7-axis arm: the robtarget's arm angle picks the axes; eax_a returns axis 7.
        Ok(Some(q)) => {
            extax[0] = q[6];
            Ok([q[0], q[1], q[2], q[3], q[4], q[5]])
        }
        Err(e) => Err(e),
        Ok(None) => chain.joints_for(&ctx.resources.robot_mut().kin, &pose, &conf, &seed, ConfMatch::Compliant),
    };
    let error_number = args.get(at.error_number).filter(|a| present(Some(a)));
    if let Some(var) = error_number {
        ctx.store(var, Value::Num(0.0))?;
    }
    let err = match found {
        Ok(joints) => return Ok(Some(super::frame::with_extax(&data::jointtarget_value(ctx, &joints)?, &extax))),
        Err(MotionError::OutOfReach) => ctx.error(Err::OutsideReach, "the robtarget is outside the robot's reach"),
        Err(other) => ctx.error(Err::RobLimit, format!("the robtarget cannot be reached: {other}")),
    };
    match error_number {
        Some(var) => {
            ctx.store(var, Value::Num(err.errno as f32))?;
            Ok(Some(data::jointtarget_value(ctx, &seed)?))
        }
        None => Err(err),
    }
}

/// `PDispOn [\Rot] [\ExeP] ProgPoint, Tool [\WObj]`: a program displacement that
/// carries ProgPoint onto ExeP, or onto where the TCP is now (a stop point should
/// come first); translation only, with the rotation too under `\Rot`; in the object
/// frame.
// uncertain: the robot's current position is taken without the displacement active
// before (the displacement is replaced, not added to).
pub(crate) fn pdisp_on(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *PDISP_ON;
    let (prog, _) = data::robtarget(ctx, &ctx.value(&args[at.prog_point])?)?;
    let actual = if present(args.get(at.exe_p)) {
        data::robtarget(ctx, &ctx.value(&args[at.exe_p])?)?.0
    } else {
        let tool = ctx.value(&args[at.tool])?;
        let wobj = if present(args.get(at.wobj)) { Some(ctx.value(&args[at.wobj])?) } else { None };
        let chain = data::chain(ctx, &tool, wobj.as_ref(), nalgebra::Isometry3::identity())?;
        let now = ctx.time;
        let robot = ctx.resources.robot_mut();
        let joints = robot.joints_at(now);
        chain.target_of(&robot.kin.forward(&joints))
    };
    let disp = rapid_motion::frames::pdisp_from(&prog, &actual, present(args.get(at.rot)));
    super::settings::set_pdisp(ctx, disp)
}

/// `EOffsOn [\ExeP] ProgPoint`: external axis offsets that carry ProgPoint's axes onto
/// ExeP's (or where the axes are now); an axis unused in either (9E9), or one the
/// system does not have, gets no offset.
pub(crate) fn eoffs_on(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *EOFFS_ON;
    let prog = data::target_extax(ctx, &ctx.value(&args[at.prog_point])?)?;
    let now = ctx.time;
    let actual = match present(args.get(at.exe_p)) {
        true => data::target_extax(ctx, &ctx.value(&args[at.exe_p])?)?,
        false => ctx.resources.robot_mut().extax_read(now),
    };
    let mut offsets = [0.0; 6];
    for ((offset, p), a) in offsets.iter_mut().zip(prog).zip(actual) {
        if p < 8.9e9 && a < 8.9e9 {
            *offset = a - p;
        }
    }
    super::settings::set_eoffs(ctx, offsets)
}
