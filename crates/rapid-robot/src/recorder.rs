//! The path recorder (§1.8, Path Recovery): PathRecStart, PathRecStop,
//! PathRecValidBwd, PathRecValidFwd, PathRecMoveBwd, PathRecMoveFwd.
//!
//! While on, the recorder keeps every move the base path is given (where it starts
//! and its request: target, interpolation, speed, zone, tool). PathRecStart's
//! `pathrecid` marks a place on it (the end of the moves given so far). After an
//! error, on path level 2 (StorePath), PathRecMoveBwd takes the robot back over the
//! moves it has executed, in reverse, with each move's own interpolation (a line
//! back along a MoveL, a joint move back along a MoveJ, the circle back along a
//! MoveC), to a mark or to where recording began; PathRecMoveFwd brings it forward
//! the same way to where PathRecMoveBwd started, so RestoPath and StartMove can go
//! on with the base path.
//!
//! `\ToolOffs` shifts the whole backward (and forward) path by an offset in the tool
//! frame: the robot first moves to the offset of where it stands, and forward it
//! ends with a move from the offset back onto the path.

use crate::RobotResources;
use nalgebra::{Isometry3, Translation3};
use rapid_motion::external::Eax;
use rapid_motion::plan::{MoveRequest, SpeedData, Target, ZoneData};
use rapid_motion::{Joints, Kinematics, Pose};

use super::moves::motion_error;
use super::robot::RobotState;
use rapid_vm::ext::{present, Ctx, Opaque, OpaqueState, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// One recorded move: where it started and what it was asked to do.
#[derive(Debug, Clone, Copy)]
struct Step {
    from: Joints,
    /// Where the external axes stood when it started (`None`: the task has none).
    eax_from: Option<Eax>,
    request: MoveRequest,
    /// It was made in a moving work object (a conveyor's, a unit's, another task's).
    in_moving_object: bool,
}

/// Where PathRecMoveBwd took the robot: back over moves `to..from`, from `at` (with
/// the external axes at `at_eax`).
#[derive(Debug, Clone, Copy)]
struct Back {
    to: usize,
    from: usize,
    at: Joints,
    at_eax: Option<Eax>,
}

/// A move the recorder gives the robot, and where it takes the external axes.
type Leg = (MoveRequest, Option<Eax>);

/// The recorder of a motion task.
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    on: bool,
    steps: Vec<Step>,
    /// The places `pathrecid`s mark: numbers of moves recorded before them. A
    /// pathrecid holds its index here.
    marks: Vec<usize>,
    back: Option<Back>,
}

impl Recorder {
    /// Records a move given to the robot, while recording.
    pub(super) fn note(&mut self, from: (Joints, Option<Eax>), request: &MoveRequest, in_moving_object: bool) {
        if self.on {
            let (from, eax_from) = from;
            self.steps.push(Step { from, eax_from, request: *request, in_moving_object });
        }
    }

    /// RestoPath: the base path takes over, PathRecMoveFwd has nothing to return to.
    pub(super) fn forget_back(&mut self) {
        self.back = None;
    }
}

/// `PathRecStart ID`: recording starts (or goes on), and ID marks the place the
/// program has come to.
// uncertain: starting again after PathRecStop (without \Clear) drops the old
// recording, since the path between the two was not recorded.
pub(crate) fn path_rec_start(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (opaque, _) = ctx.handle_arg(&args[0], "a pathrecid")?;
    let rec = &mut ctx.resources.robot_mut().path_rec;
    if !rec.on {
        *rec = Recorder { on: true, ..Recorder::default() };
    }
    rec.marks.push(rec.steps.len());
    let index = rec.marks.len() - 1;
    let data = Opaque { ty: opaque.ty, state: OpaqueState::Handle(index as u32) };
    ctx.store(&args[0], Value::Opaque(Box::new(data)))?;
    Ok(None)
}

/// `PathRecStop [\Clear]`: recording stops; `\Clear` forgets the recorded path.
pub(crate) fn path_rec_stop(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let rec = &mut ctx.resources.robot_mut().path_rec;
    rec.on = false;
    if present(args.first()) {
        *rec = Recorder::default();
    }
    Ok(None)
}

/// The number of recorded moves a `\ID` argument marks: None when absent, an error
/// when the pathrecid was never set by PathRecStart.
fn mark(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<Option<usize>, RapidError> {
    let Some(arg) = arg.filter(|a| present(Some(a))) else { return Ok(None) };
    let (_, handle) = ctx.handle_arg(arg, "a pathrecid")?;
    let rec = &ctx.resources.robot().path_rec;
    match handle.and_then(|h| rec.marks.get(h as usize)) {
        Some(&n) => Ok(Some(n)),
        None => Err(RapidError::fatal("the pathrecid was not set by PathRecStart (or the recording was cleared)")),
    }
}

/// How many recorded moves the robot has started (the rest were given but not
/// begun when the base path stopped).
fn executed(robot: &RobotState, now: f64) -> usize {
    let unstarted = match &robot.stored {
        Some(stored) => stored.unstarted(),
        None => {
            let queued = robot.ahead.iter().filter(|m| m.start > now && m.duration() > 0.0).count();
            queued + usize::from(robot.planner.has_pending() && robot.planner.time() > now)
        }
    };
    robot.path_rec.steps.len().saturating_sub(unstarted)
}

/// How far along the recorded moves the robot is: the moves it has started, or,
/// after PathRecMoveBwd, the place that took it back to.
fn behind(robot: &RobotState, now: f64) -> usize {
    match robot.path_rec.back {
        Some(back) => back.to,
        None => executed(robot, now),
    }
}

/// `PathRecValidBwd([\ID])`: whether the recorder is on and the robot has a recorded
/// path behind it (back to ID).
pub(crate) fn path_rec_valid_bwd(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let to = mark(ctx, args.first())?;
    let robot = ctx.resources.robot_mut();
    let valid = robot.path_rec.on && behind(robot, ctx.time) > to.unwrap_or(0);
    Ok(Some(Value::Bool(valid)))
}

/// `PathRecValidFwd([\ID])`: whether PathRecMoveBwd took the robot back and it can
/// go forward again (to ID).
pub(crate) fn path_rec_valid_fwd(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let to = mark(ctx, args.first())?;
    let valid = match ctx.resources.robot_mut().path_rec.back {
        Some(back) => to.is_none_or(|n| n > back.to && n <= back.from),
        None => false,
    };
    Ok(Some(Value::Bool(valid)))
}

/// The path recorder moves the robot on path level 2 only.
// uncertain: the manual's examples always StorePath first; on the base path the
// moves would mix with the stopped path, so they are refused.
fn require_level_2(ctx: &Ctx<'_>, what: &str) -> Result<(), RapidError> {
    if ctx.resources.robot().stored.is_none() {
        return Err(RapidError::fatal(format!("{what} moves the robot on path level 2: StorePath first")));
    }
    Ok(())
}

/// The `\ToolOffs` pos argument as a shift in the tool frame. The manual: a
/// positive z is clearance, so z moves the TCP back along the tool's z axis (out
/// of the work); x and y go along the tool's axes.
// uncertain: the signs of the offset (the manual only says positive z is clearance).
fn tool_offset(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<Option<Pose>, RapidError> {
    let Some(arg) = arg.filter(|a| present(Some(a))) else { return Ok(None) };
    let value = ctx.value(arg)?;
    let Value::Record(pos) = &value else {
        return Err(ctx.error(rapid_vm::ext::Err::ArgValue, "\\ToolOffs: a pos was expected"));
    };
    let n = |i: usize| pos.fields.get(i).and_then(Value::as_f64).unwrap_or(0.0);
    Ok(Some(Isometry3::from_parts(Translation3::new(n(0), n(1), -n(2)), Default::default())))
}

/// The `\Speed` argument, or None (each move's recorded speed).
fn speed_arg(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<Option<SpeedData>, RapidError> {
    match arg.filter(|a| present(Some(a))) {
        Some(arg) => Ok(Some(super::data::speed(ctx, &ctx.value(arg)?)?)),
        None => Ok(None),
    }
}

/// What one step of the way back or forward is: a move of `step`'s interpolation to
/// `to` (joints), the circle through its CirPoint when `whole`.
fn target(robot: &RobotState, step: &Step, to: Joints, whole: bool, offs: Option<Pose>) -> Result<Target, RapidError> {
    let mount = step.request.mount();
    let offs = offs.unwrap_or_else(Pose::identity);
    let tcp = mount.path_pose(&robot.kin.forward(&to)) * offs;
    Ok(match step.request.target {
        Target::Joints(_) if offs == Pose::identity() => Target::Joints(to),
        Target::Joints(_) => Target::Joints(robot.kin.inverse_near(&mount.flange(&tcp), &to).map_err(motion_error)?),
        Target::Circular { via, .. } if whole => Target::Circular { via: via * offs, to: tcp },
        Target::Linear(_) | Target::Circular { .. } => Target::Linear(tcp),
    })
}

/// The recorder replays moves relative to the robot's base: a move made in a work
/// object that moved meanwhile (a conveyor's, a unit's) stops execution rather than
/// take the robot where the object no longer is.
fn no_moving_objects(steps: &[Step], what: &str) -> Result<(), RapidError> {
    if steps.iter().any(|s| s.in_moving_object) {
        return Err(RapidError::fatal(format!(
            "{what}: the recorded path was made in a moving work object (a conveyor's or a unit's); \
             moving along it is not supported yet"
        )));
    }
    Ok(())
}

/// A `\Speed` given to the recorder as the planner needs it for a linear leg from
/// `from` to `to` while the track carries the robot: the TCP keeps it in the world (the
/// recorded speeds were scaled so when the moves were given).
fn scaled(
    robot: &RobotState,
    speed: SpeedData,
    step: &Step,
    from: (Joints, Option<Eax>),
    to: (&Target, Option<Eax>),
) -> SpeedData {
    let (Target::Linear(to_pose), Some(a), Some(b)) = (to.0, from.1, to.1) else { return speed };
    let Some((axis, dir)) = robot.external.track() else { return speed };
    let shift = robot.in_base(dir * (b[axis] - a[axis]));
    let from_tcp = step.request.mount().path_pose(&robot.kin.forward(&from.0)).translation.vector;
    let scale = super::track::relative_over_world(from_tcp, to_pose.translation.vector, shift);
    SpeedData { v_tcp: speed.v_tcp * scale, ..speed }
}

/// Whether the robot at `at` stands at the end of `step` (it finished the move).
fn at_end(robot: &RobotState, step: &Step, at: &Joints) -> bool {
    let mount = step.request.mount();
    let end = match step.request.target {
        Target::Joints(q) => mount.path_pose(&robot.kin.forward(&q)),
        Target::Linear(p) | Target::Circular { to: p, .. } => p,
    };
    let here = mount.path_pose(&robot.kin.forward(at));
    (end.translation.vector - here.translation.vector).norm() < 0.01
}

/// Gives the robot `legs` (on level 2) and makes the program wait until it stands at
/// the last one. The external axes go where each leg takes them, on the arm's profile;
/// a track carrying the robot keeps a circle in the world as the move did.
fn run(ctx: &mut Ctx<'_>, legs: &[Leg]) -> Result<(), RapidError> {
    let settings = super::moves::planner_settings(ctx);
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    for (request, eax) in legs {
        let mut settings = settings;
        if let (Some(to), Some(from)) = (eax, robot.planner.end_eax()) {
            let ext = robot.external.plan(from, to, None, robot.independent.external_mask()).map_err(motion_error)?;
            if let Target::Circular { .. } = request.target {
                settings.base_travel = super::track::track_travel(robot, &ext).into();
            }
            robot.next_external = Some(ext);
        }
        robot.set_settings(settings);
        robot.push(now, request, true, Vec::new()).map_err(motion_error)?;
    }
    let end = robot.flush();
    if end > now {
        ctx.wait = Some(end - now);
    }
    Ok(())
}

/// A linear move to the TCP of `joints` shifted by `offs`, with `step`'s tool.
fn to_offset(
    robot: &RobotState,
    step: &Step,
    joints: &Joints,
    offs: Pose,
    speed: SpeedData,
    zone: ZoneData,
) -> MoveRequest {
    let tcp = step.request.mount().path_pose(&robot.kin.forward(joints)) * offs;
    MoveRequest { target: Target::Linear(tcp), speed, zone, ..step.request }
}

/// `PathRecMoveBwd [\ID] [\ToolOffs] [\Speed]`: the robot goes back along the
/// recorded path to ID (or where recording began).
// uncertain: without \Speed each move goes back at its recorded speed; the zones
// on the way are the recorded ones, the end is a stop point.
pub(crate) fn path_rec_move_bwd(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    require_level_2(ctx, "PathRecMoveBwd")?;
    let to = mark(ctx, args.first())?.unwrap_or(0);
    let offs = tool_offset(ctx, args.get(1))?;
    let speed = speed_arg(ctx, args.get(2))?;
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    robot.flush();
    let done = behind(robot, now);
    if !robot.path_rec.on || done <= to {
        return Err(RapidError::fatal("PathRecMoveBwd: no recorded path behind the robot (PathRecValidBwd is FALSE)"));
    }
    no_moving_objects(&robot.path_rec.steps[to..done], "PathRecMoveBwd")?;
    let (at, at_eax) = (robot.end_joints(), robot.planner.end_eax());
    // Back again from a place PathRecMoveBwd took it to: whole moves only, and
    // forward still returns to where the first one started.
    let earlier = robot.path_rec.back;
    let steps = &robot.path_rec.steps;
    let mut legs = Vec::new();
    if let Some(offs) = offs {
        let last = &steps[done - 1];
        let speed = speed.unwrap_or(last.request.speed);
        legs.push((to_offset(robot, last, &at, offs, speed, ZoneData::FINE), at_eax));
    }
    let mut here = (at, at_eax);
    for i in (to..done).rev() {
        let step = &steps[i];
        let whole = i + 1 < done || earlier.is_some() || at_end(robot, step, &at);
        let zone = if i == to { ZoneData::FINE } else { steps[i - 1].request.zone };
        let target = target(robot, step, step.from, whole, offs)?;
        let speed = speed.map_or(step.request.speed, |s| scaled(robot, s, step, here, (&target, step.eax_from)));
        legs.push((MoveRequest { target, speed, zone, ..step.request }, step.eax_from));
        here = (step.from, step.eax_from);
    }
    robot.path_rec.back = Some(earlier.map_or(Back { to, from: done, at, at_eax }, |b| Back { to, ..b }));
    run(ctx, &legs)?;
    Ok(None)
}

/// `PathRecMoveFwd [\ID] [\ToolOffs] [\Speed]`: the robot goes forward along the
/// recorded path to ID, or to where PathRecMoveBwd started.
pub(crate) fn path_rec_move_fwd(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    require_level_2(ctx, "PathRecMoveFwd")?;
    let until = mark(ctx, args.first())?;
    let offs = tool_offset(ctx, args.get(1))?;
    let speed = speed_arg(ctx, args.get(2))?;
    let robot = ctx.resources.robot_mut();
    robot.flush();
    let Some(back) = robot.path_rec.back else {
        return Err(RapidError::fatal(
            "PathRecMoveFwd: PathRecMoveBwd has not taken the robot back (PathRecValidFwd is FALSE)",
        ));
    };
    let end = match until {
        Some(n) if n > back.to && n <= back.from => n,
        Some(_) => {
            return Err(RapidError::fatal(
                "PathRecMoveFwd: the pathrecid is not ahead of the robot on the recorded path",
            ))
        }
        None => back.from,
    };
    no_moving_objects(&robot.path_rec.steps[back.to..end], "PathRecMoveFwd")?;
    let steps = &robot.path_rec.steps;
    let mut legs = Vec::new();
    let mut here = (robot.end_joints(), robot.planner.end_eax());
    for i in back.to..end {
        let step = &steps[i];
        let (to, to_eax, whole) = match steps.get(i + 1) {
            Some(next) if i + 1 < back.from => (next.from, next.eax_from, true),
            _ => (back.at, back.at_eax, at_end(robot, step, &back.at)),
        };
        let zone = if i + 1 == end && offs.is_none() { ZoneData::FINE } else { step.request.zone };
        let target = target(robot, step, to, whole, offs)?;
        let speed = speed.map_or(step.request.speed, |s| scaled(robot, s, step, here, (&target, to_eax)));
        legs.push((MoveRequest { target, speed, zone, ..step.request }, to_eax));
        here = (to, to_eax);
    }
    if offs.is_some() && end > back.to {
        let step = &steps[end - 1];
        let to = if end == back.from { back.at } else { steps[end].from };
        let tcp = step.request.mount().path_pose(&robot.kin.forward(&to));
        let speed = speed.unwrap_or(step.request.speed);
        legs.push((MoveRequest { target: Target::Linear(tcp), speed, zone: ZoneData::FINE, ..step.request }, here.1));
    }
    robot.path_rec.back = (end < back.from).then_some(Back { to: end, ..back });
    run(ctx, &legs)?;
    Ok(None)
}
