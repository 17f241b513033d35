//! The move instructions (§1.8, §2.2–2.3): MoveJ, MoveL, MoveC, MoveAbsJ, and WaitRob.
//! Each computes where the robot goes (inverse kinematics by the programmed
//! configuration for MoveJ, ConfJ\Off the closest solution), hands the move to the
//! task's planner and makes the program wait as the controller would: until the
//! robot stands at a stop point, until shortly before a fly-by point, not at all
//! with `\Conc`. Unreachable targets stop execution with the controller's motion error.

use crate::RobotResources;
use rapid_motion::confdata::{inverse_nearest, ConfMatch};
use rapid_motion::plan::{CircleOri, MotionSettings, MoveRequest, Target};
use rapid_motion::MotionError;

use super::data;
pub(super) use super::layout::{EOffsRule, Layout};
use super::layout::{
    MOVE_ABS_J, MOVE_C, MOVE_C_AO, MOVE_C_DO, MOVE_C_GO, MOVE_C_SYNC, MOVE_J, MOVE_J_AO, MOVE_J_DO, MOVE_J_GO,
    MOVE_J_SYNC, MOVE_L, MOVE_L_AO, MOVE_L_DO, MOVE_L_GO, MOVE_L_SYNC,
};
use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// The controller's motion errors: execution stops (they are not program errors an
/// ERROR handler can take). Event numbers as RobotWare logs them.
// uncertain: the event numbers are from memory of RobotWare's event log.
pub(crate) fn motion_error(err: MotionError) -> RapidError {
    let (code, text) = match err {
        MotionError::OutOfReach => (50050, "Position outside reach".to_string()),
        MotionError::JointLimit { axis } => (50028, format!("Joint {axis} out of range")),
        MotionError::Configuration => (50080, "Position not compatible (the programmed configuration)".to_string()),
        MotionError::Singularity => (50026, "Close to singularity".to_string()),
        MotionError::DegenerateCircle => {
            (50063, "Circle uncertain (the circle points are too close or on a line)".to_string())
        }
        MotionError::InvalidData(what) => return RapidError::fatal(format!("invalid motion data: {what}")),
    };
    // The motion system reports these, in its own domain of the event log.
    RapidError::motion(code, format!("{code} {text}"))
}

/// The speed and zone of a move, with `\V` and `\Z`.
fn speed_and_zone(
    ctx: &Ctx<'_>,
    args: &[Value],
    layout: &Layout,
) -> Result<(rapid_motion::plan::SpeedData, rapid_motion::plan::ZoneData), RapidError> {
    let mut speed = data::speed(ctx, &ctx.value(&args[layout.speed])?)?;
    if let Some(v) = ctx.opt_num(args.get(layout.v))? {
        speed.v_tcp = v;
    }
    let mut zone = data::zone(ctx, &ctx.value(&args[layout.zone])?)?;
    if let Some(z) = ctx.opt_num(args.get(layout.z))? {
        zone.pzone_tcp = z;
    }
    Ok((speed, zone))
}

/// The settings moves are planned with (VelSet, AccSet, the operator's and the
/// task's speed overrides; manual reduced speed caps the TCP at 250 mm/s).
pub(super) fn planner_settings(ctx: &Ctx<'_>) -> MotionSettings {
    let s = &ctx.resources.motion().settings;
    let controller = &ctx.resources.controller;
    let vel_max = controller.tcp_speed_limit().map_or(s.vel_max, |limit| s.vel_max.min(limit));
    MotionSettings {
        acc: s.acc,
        ramp: s.ramp,
        vel_override: s.vel_override,
        vel_max,
        speed_override: controller.speed_override * s.speed_refresh / 100.0,
        circle_ori: match s.cir_path_mode {
            super::CirPathMode::ObjectFrame => CircleOri::ObjectFrame,
            super::CirPathMode::CirPointOri => CircleOri::CirPointOri,
            // The wrist modes are refused before a circle is planned.
            _ => CircleOri::PathFrame,
        },
        move_time: None,
        stop_time: None,
        // m/s² to mm/s²; a world-frame limit bounds the path's too.
        tcp_acc_max: min_limit(s.acc_max, s.world_acc_max).map(|a| a * 1000.0),
        tcp_dec_max: min_limit(s.decel_max, s.world_acc_max).map(|a| a * 1000.0),
        sing_wrist: s.sing == super::SingMode::Wrist,
        base_travel: [0.0; 3],
    }
}

/// The smaller of two optional limits.
fn min_limit(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// A circle is planned only with the CirPathMode orientations the planner models.
pub(super) fn check_circle_mode(ctx: &Ctx<'_>) -> Result<(), RapidError> {
    use super::CirPathMode::{Wrist45, Wrist46, Wrist56};
    let mode = ctx.resources.motion().settings.cir_path_mode;
    if matches!(mode, Wrist45 | Wrist46 | Wrist56) {
        return Err(RapidError::fatal(format!(
            "circular moves with CirPathMode \\{mode:?} are not supported by `rapid run` yet"
        )));
    }
    Ok(())
}

/// Linear and circular moves are planned with SingArea \Off or \Wrist; \LockAxis4
/// (axis 4 held at 0° or ±180°) is not modelled.
pub(super) fn check_sing_mode(ctx: &Ctx<'_>) -> Result<(), RapidError> {
    if ctx.resources.motion().settings.sing == super::SingMode::LockAxis4 {
        return Err(RapidError::fatal(
            "linear and circular moves with SingArea \\LockAxis4 are not supported by `rapid run` yet",
        ));
    }
    Ok(())
}

/// Only a motion task (`-MotionTask`) runs move instructions (§1.20).
pub(super) fn require_motion_task(ctx: &Ctx<'_>) -> Result<(), RapidError> {
    if rapid_tasks::my_task(ctx).is_none_or(|t| t.motion) {
        return Ok(());
    }
    let name = ctx.resources.tasks.name();
    Err(RapidError::fatal(format!("task {name} is no motion task (-MotionTask): it cannot move the robot")))
}

/// Whether this task moves a robot (a positioner's motion task moves external units
/// only).
pub(super) fn moves_robot(ctx: &Ctx<'_>) -> bool {
    rapid_tasks::my_task(ctx).is_none_or(|t| t.robot)
}

/// A move of the TCP runs only in a motion task that moves a robot.
// uncertain: the controller's error for a TCP move in a task whose mechanical unit
// group has no robot is not in our sources; execution stops.
pub(super) fn require_robot(ctx: &Ctx<'_>) -> Result<(), RapidError> {
    require_motion_task(ctx)?;
    if moves_robot(ctx) {
        return Ok(());
    }
    Err(RapidError::fatal(format!(
        "task {} moves no robot (its mechanical units are external axes only): it cannot move a TCP; MoveExtJ \
         and MoveAbsJ move its axes",
        ctx.resources.tasks.name()
    )))
}

/// Plans the move (with the events it fires on its path) and makes the program wait
/// until it may go on.
pub(super) fn go_with(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    layout: &Layout,
    target: Target,
    chain: rapid_motion::frames::FrameChain,
    events: Vec<super::robot::PathEvent>,
) -> Res {
    let (speed, mut zone) = speed_and_zone(ctx, args, layout)?;
    if ctx.resources.controller.run_mode.moves_end_at_targets() {
        // Stepped: the step ends with the robot at the target (RunMode's rule).
        zone = rapid_motion::plan::ZoneData::FINE;
    }
    let mut settings = planner_settings(ctx);
    // `\T`: the move's time; `\Inpos`: a stop point of its own in place of the zone.
    settings.move_time = ctx.opt_num(args.get(layout.t))?;
    let stop = match args.get(layout.inpos) {
        Some(inpos) if present(Some(inpos)) => {
            let settle = rapid_motion::plan::AccelLimits::nominal(&ctx.resources.robot_mut().model.max_speeds).settle;
            Some(super::inpos::stop_point(ctx, &ctx.value(inpos)?, settle)?)
        }
        _ => None,
    };
    if let Some(stop) = stop {
        zone = rapid_motion::plan::ZoneData::FINE;
        settings.stop_time = Some(stop.time);
    }
    let (tool, held_object) = mount_of(&chain);
    let mut request = MoveRequest { target, speed, zone, tool, held_object, wobj: wobj_frame(&chain) };
    let external = external_target(ctx, args, layout.to, layout.eoffs);
    // A 7-axis arm's axis 7 at a robtarget's target is taken by this move alone.
    ctx.resources.robot_mut().next_axis7 = None;
    let external = external?;
    if let Some(ext) = &external {
        request.speed.v_tcp *= super::track::track_speed_scale(ctx.resources.robot_mut(), &target, &chain, ext)?;
        if let Target::Circular { .. } = target {
            settings.base_travel = super::track::track_travel(ctx.resources.robot_mut(), ext).into();
        }
    }
    // Synchronized movement: the moves of one `\ID` in all tasks take the same time.
    match super::syncmove::coordinate(ctx, args.get(layout.id), &request, &settings, external.as_ref())? {
        super::syncmove::Coordination::Alone => {}
        super::syncmove::Coordination::Wait => return Ok(None),
        super::syncmove::Coordination::Time(time) if time > 0.0 => settings.move_time = Some(time),
        // Every robot of the group already stands at its target: no common time to
        // give (a zero \T is invalid), each move is the zero-length move it is alone.
        super::syncmove::Coordination::Time(_) => {}
    }
    note_facts(ctx, &request, &chain);
    let now = ctx.time;
    let conc = present(args.get(layout.conc));
    count_conc(ctx, conc, now)?;
    let robot = ctx.resources.robot_mut();
    robot.set_settings(settings);
    robot.next_external = external;
    // `\Corr`: the path follows the corrections of the connected generators.
    robot.corr.next = layout.corr.is_some_and(|c| present(args.get(c)));
    let foreign = robot.next_foreign;
    let mut resume = robot.push(now, &request, conc, events).map_err(motion_error)?;
    if let Some(err) = robot.corr.violation.take() {
        return Err(motion_error(err));
    }
    super::tracking::check_reach(robot, resume)?;
    if let Some(stop) = stop.filter(|s| !s.progsynch && !conc) {
        // progsynch FALSE: the program goes on once the robot stands at the point.
        resume = (resume - stop.time).max(now);
    }
    robot.active = chain;
    robot.active_foreign = foreign;
    apply_due_events(ctx)?;
    if ctx.resources.robot_mut().zone_violation.take().is_some() {
        // uncertain: RobotWare's event number for a WZLimSup stop is not in our notes.
        return Err(RapidError::fatal("world zone: the robot would enter a WZLimSup zone; it stops before it"));
    }
    // The move's tool and work object become the active ones (CTool, CWObj, GetSysData).
    if let Some(tool) = args.get(layout.tool) {
        super::sysdata::activate_arg(ctx, tool, layout.tool, 0);
    }
    if present(args.get(layout.wobj)) {
        super::sysdata::activate_arg(ctx, &args[layout.wobj], layout.wobj, 1);
    }
    wait_for_robot(ctx, resume);
    Ok(None)
}

/// The external axes' part of the move to the target at `to` (a robtarget's or
/// jointtarget's `extax`, its last field), with the offsets `rule` allows.
pub(super) fn external_target(
    ctx: &Ctx<'_>,
    args: &[Value],
    to: usize,
    rule: EOffsRule,
) -> Result<Option<rapid_motion::external::ExternalMove>, RapidError> {
    if !ctx.resources.robot().external.any() {
        return Ok(None);
    }
    let target = ctx.value(&args[to])?;
    let values = data::target_extax(ctx, &target)?;
    let use_offsets = match rule {
        EOffsRule::Always => true,
        EOffsRule::Unless(switch) => !present(args.get(switch)),
        EOffsRule::Only(switch) => present(args.get(switch)),
    };
    let offsets = use_offsets.then_some(ctx.resources.motion().settings.eoffs);
    let external = ctx.resources.robot().external_move(&values, offsets.as_ref()).map_err(motion_error)?;
    if let Some(ext) = &external {
        // A unit another task's robot works in moves only as MultiMove allows.
        super::foreign::check_unit_move(ctx, &ext.from, &ext.to)?;
    }
    Ok(external)
}

/// The most consecutive moves with `\Conc` (the instruction manual: "the number of
/// consecutive movement instructions is limited to 5").
const MAX_CONC: u32 = 5;

/// Counts a move given with `\Conc` (`conc`): a sixth in a row raises ERR_CONC_MAX; a
/// move without it, or the robot standing still when it is given (every move before
/// it done), ends the row. A `\Conc` move while StorePath holds the base path stops
/// execution (the manual does not allow one between StorePath and RestoPath).
// uncertain: that the row ends when the robot has caught up, and where the error is
// raised (at the sixth move, before the robot is given it).
fn count_conc(ctx: &mut Ctx<'_>, conc: bool, now: f64) -> Result<(), RapidError> {
    let robot = ctx.resources.robot_mut();
    if !conc || robot.still_from() <= now {
        robot.conc_run = 0;
    }
    if !conc {
        return Ok(());
    }
    if robot.stored.is_some() {
        return Err(RapidError::fatal("a move with \\Conc is not allowed between StorePath and RestoPath"));
    }
    if robot.conc_run >= MAX_CONC {
        let message = format!("more than {MAX_CONC} consecutive movement instructions with \\Conc");
        return Err(ctx.error(rapid_vm::ext::Err::ConcMax, message));
    }
    robot.conc_run += 1;
    Ok(())
}

/// The program waits for the robot until `resume`.
pub(super) fn wait_for_robot(ctx: &mut Ctx<'_>, resume: f64) {
    let now = ctx.time;
    if resume <= now {
        return;
    }
    // Inside a TRAP no other trap can start (interrupts queue): the move waits whole.
    let in_trap = ctx.in_trap();
    if in_trap {
        ctx.wait = Some(resume - now);
        return;
    }
    // The rest of the wait is held before the next instruction (the VM), so a stop of
    // the robot meanwhile (a trap's StopMove, another task's `\AllMotionTasks`, a
    // program stop) holds the program too.
    ctx.resources.robot_mut().hold_until = Some(resume);
    if ctx.resources.interrupts.active() {
        // Interrupts may come while the robot moves: wait until the next one may.
        let next = rapid_vm::ext::next_due(ctx).map_or(resume, |due| due.min(resume));
        ctx.wait = Some((next - now).max(1e-6));
    } else {
        ctx.wait = Some(resume - now);
    }
}

/// The frames of this move: its tool and work object, and the displacement.
fn frames(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    layout: &Layout,
    displaced: bool,
) -> Result<rapid_motion::frames::FrameChain, RapidError> {
    let mut chain = frames_at(ctx, args, layout.tool, layout.wobj, displaced)?;
    on_track(ctx, args, layout.to, layout.eoffs, &mut chain)?;
    Ok(chain)
}

/// On a track, a move's target is reached with the robot's base where the track will
/// be then: the target's track value.
pub(super) fn on_track(
    ctx: &Ctx<'_>,
    args: &[Value],
    to: usize,
    rule: EOffsRule,
    chain: &mut rapid_motion::frames::FrameChain,
) -> Result<(), RapidError> {
    if ctx.resources.robot().external.track().is_none() {
        return Ok(());
    }
    if let Some(ext) = external_target(ctx, args, to, rule)? {
        chain.base = ctx.resources.robot().track_base(&ext.to);
    }
    Ok(())
}

/// The frames of the tool and (optional) work object arguments at these places, for a
/// move about to be given: a conveyor's work object is taken where the robot's
/// tracking froze it (see `tracking.rs`).
pub(super) fn frames_at(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    tool: usize,
    wobj: usize,
    displaced: bool,
) -> Result<rapid_motion::frames::FrameChain, RapidError> {
    let tool = ctx.value(&args[tool])?;
    let wobj = if present(args.get(wobj)) { Some(ctx.value(&args[wobj])?) } else { None };
    let carrier = super::tracking::begin_move(ctx, wobj.as_ref())?;
    let pdisp = if displaced { ctx.resources.motion_mut().settings.pdisp } else { nalgebra::Isometry3::identity() };
    let mut chain = data::chain(ctx, &tool, wobj.as_ref(), pdisp)?;
    if let Some(uframe) = carrier.and_then(|c| super::tracking::planning_frame(ctx, c)) {
        chain.uframe = uframe;
    }
    Ok(chain)
}

/// `MoveJ`: joint interpolation to a robtarget, reached in its programmed
/// configuration (ConfJ\On) or the closest one (ConfJ\Off).
pub(crate) fn move_j(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    joint_move(ctx, args, &MOVE_J, Vec::new())
}

/// MoveJ and MoveJDO/AO/GO: joint interpolation to a robtarget.
pub(super) fn joint_move(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    layout: &Layout,
    events: Vec<super::robot::PathEvent>,
) -> Res {
    require_robot(ctx)?;
    let chain = frames(ctx, args, layout, true)?;
    let target = ctx.value(&args[layout.to])?;
    let (pose, conf) = data::robtarget(ctx, &target)?;
    if let Some(q) = arm_target(ctx, &chain, &target)? {
        // A 7-axis arm: the target's arm angle, not its configuration, picks the axes.
        let joints = [q[0], q[1], q[2], q[3], q[4], q[5]];
        return go_with(ctx, args, layout, Target::Joints(joints), chain, events);
    }
    let robot = ctx.resources.robot();
    let seed = robot.end_joints();
    let joints = if ctx.resources.motion().settings.conf_j {
        chain.joints_for(&robot.kin, &pose, &conf, &seed, ConfMatch::Compliant)
    } else {
        inverse_nearest(&robot.kin, &chain.flange_goal(&pose), &seed)
    }
    .map_err(motion_error)?;
    go_with(ctx, args, layout, Target::Joints(joints), chain, events)
}

/// A 7-axis arm's seven axes at a robtarget move's target (its arm angle in eax_a),
/// axis 7 kept for the move (`arm7.rs`); `None` for other robots.
pub(super) fn arm_target(
    ctx: &mut Ctx<'_>,
    chain: &rapid_motion::frames::FrameChain,
    target: &Value,
) -> Result<Option<rapid_motion::kinematics::yumi::Joints7>, RapidError> {
    if !super::arm7::has_axis7(ctx.resources.robot_mut()) {
        return Ok(None);
    }
    let (pose, _) = data::robtarget(ctx, target)?;
    let extax = data::target_extax(ctx, target)?;
    super::arm7::target_axis7(ctx, &chain.flange_goal(&pose), &extax)
}

/// `MoveL`: a straight TCP line to a robtarget (ConfL\On: see `check_conf_l`).
pub(crate) fn move_l(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    linear_move(ctx, args, &MOVE_L, Vec::new())
}

/// MoveL and MoveLDO/AO/GO.
pub(super) fn linear_move(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    layout: &Layout,
    events: Vec<super::robot::PathEvent>,
) -> Res {
    require_robot(ctx)?;
    check_sing_mode(ctx)?;
    let chain = frames(ctx, args, layout, true)?;
    let target = ctx.value(&args[layout.to])?;
    let to = tcp_in_base(ctx, &chain, &target)?;
    arm_target(ctx, &chain, &target)?;
    let result = go_with(ctx, args, layout, Target::Linear(to), chain, events)?;
    check_conf_l(ctx, &target)?;
    Ok(result)
}

/// ConfL\On: a linear or circular move keeps the configuration it starts in; it must
/// end in the programmed one (cf1, cf4, cf6 within a quadrant, cfx equal), else
/// execution stops.
// uncertain: the controller also watches axes 1, 4, 6 along the path; only the end is
// checked here, with the same neighbours ConfJ accepts.
// A 7-axis arm's target is reached by its arm angle: its confdata is not checked.
// uncertain: the YuMi's use of confdata in moves is not in the public record.
fn check_conf_l(ctx: &Ctx<'_>, target: &Value) -> Result<(), RapidError> {
    if !ctx.resources.motion().settings.conf_l || super::arm7::has_axis7(ctx.resources.robot()) {
        return Ok(());
    }
    let (_, programmed) = data::robtarget(ctx, target)?;
    let robot = ctx.resources.robot();
    let reached = rapid_motion::confdata::confdata_of(&robot.kin, &robot.end_joints());
    let near = (0..3).all(|i| (reached[i] - programmed[i]).abs() <= 1) && reached[3] == programmed[3];
    if near {
        return Ok(());
    }
    Err(RapidError::fatal(format!(
        "50080 Position not compatible: the move ends in configuration {reached:?}, not the programmed {programmed:?} (ConfL\\On; ConfL\\Off follows the path's)"
    )))
}
/// `MoveC`: a circle through CirPoint to ToPoint.
pub(crate) fn move_c(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    circular_move(ctx, args, &MOVE_C, Vec::new())
}

/// MoveC and MoveCDO/AO/GO.
pub(super) fn circular_move(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    layout: &Layout,
    events: Vec<super::robot::PathEvent>,
) -> Res {
    require_robot(ctx)?;
    check_circle_mode(ctx)?;
    check_sing_mode(ctx)?;
    let chain = frames(ctx, args, layout, true)?;
    let via = tcp_in_base(ctx, &chain, &ctx.value(&args[layout.cir.unwrap_or(1)])?)?;
    let target = ctx.value(&args[layout.to])?;
    let to = tcp_in_base(ctx, &chain, &target)?;
    arm_target(ctx, &chain, &target)?;
    let result = go_with(ctx, args, layout, Target::Circular { via, to }, chain, events)?;
    check_conf_l(ctx, &target)?;
    Ok(result)
}

/// The output a Move*DO/AO/GO sets: its signal and value (a group's `\Dvalue` too).
fn path_event(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout) -> Result<Vec<super::robot::PathEvent>, RapidError> {
    use super::robot::{Action, At, PathEvent};
    let id = rapid_signals::signal(ctx, &args[layout.signal])?;
    let value = match layout.dvalue.and_then(|at| args.get(at)) {
        Some(dvalue) if present(Some(dvalue)) => ctx.num(dvalue)?,
        _ => ctx.num(&args[layout.value])?,
    };
    Ok(vec![PathEvent { at: At::Point, shift: 0.0, action: Action::Set { signal: id, value } }])
}

/// MoveJ setting an output in the middle of the corner path (at a stop point, when
/// the robot stands there).
fn joint_move_io(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout) -> Res {
    let event = path_event(ctx, args, layout)?;
    joint_move(ctx, args, layout, event)
}

/// MoveL setting an output in the middle of the corner path.
fn linear_move_io(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout) -> Res {
    let event = path_event(ctx, args, layout)?;
    linear_move(ctx, args, layout, event)
}

/// MoveC setting an output in the middle of the corner path.
fn circular_move_io(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout) -> Res {
    let event = path_event(ctx, args, layout)?;
    circular_move(ctx, args, layout, event)
}

/// `MoveJDO`.
pub(crate) fn move_j_do(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    joint_move_io(ctx, args, &MOVE_J_DO)
}

/// `MoveJAO`.
pub(crate) fn move_j_ao(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    joint_move_io(ctx, args, &MOVE_J_AO)
}

/// `MoveJGO`.
pub(crate) fn move_j_go(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    joint_move_io(ctx, args, &MOVE_J_GO)
}

/// `MoveLDO`.
pub(crate) fn move_l_do(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    linear_move_io(ctx, args, &MOVE_L_DO)
}

/// `MoveLAO`.
pub(crate) fn move_l_ao(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    linear_move_io(ctx, args, &MOVE_L_AO)
}

/// `MoveLGO`.
pub(crate) fn move_l_go(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    linear_move_io(ctx, args, &MOVE_L_GO)
}

/// `MoveCDO`.
pub(crate) fn move_c_do(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    circular_move_io(ctx, args, &MOVE_C_DO)
}

/// `MoveCAO`.
pub(crate) fn move_c_ao(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    circular_move_io(ctx, args, &MOVE_C_AO)
}

/// `MoveCGO`.
pub(crate) fn move_c_go(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    circular_move_io(ctx, args, &MOVE_C_GO)
}

/// `MoveJSync`, `MoveLSync`, `MoveCSync`: the move runs procedure ProcName (no
/// parameters) when the robot passes the point (the middle of the corner path, or
/// standing at a stop point), as an interrupt's trap runs: between instructions, or
/// while the program waits.
// uncertain: the procedure runs like a trap (IDisable holds it back); a name that is
// no loaded procedure is ERR_REFUNKPRC, a procedure with parameters ERR_CALLPROC.
pub(crate) fn move_j_sync(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let event = sync_event(ctx, &args[MOVE_J_SYNC.proc_name])?;
    joint_move(ctx, args, &MOVE_J_SYNC, event)
}

pub(crate) fn move_l_sync(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let event = sync_event(ctx, &args[MOVE_L_SYNC.proc_name])?;
    linear_move(ctx, args, &MOVE_L_SYNC, event)
}

pub(crate) fn move_c_sync(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let event = sync_event(ctx, &args[MOVE_C_SYNC.proc_name])?;
    circular_move(ctx, args, &MOVE_C_SYNC, event)
}

/// The path event of Move*Sync: the named procedure, run at the point.
fn sync_event(ctx: &mut Ctx<'_>, name: &Value) -> Result<Vec<super::robot::PathEvent>, RapidError> {
    let name = ctx.string(name)?;
    let Some(&routine) = ctx.procs_by_name.get(&name.to_lowercase()) else {
        return Err(ctx.error(rapid_vm::ext::Err::RefUnknownProc, format!("no procedure `{name}` is loaded")));
    };
    let callable = ctx.routines.get(routine as usize).and_then(|c| c.as_ref());
    if !callable.is_some_and(|c| !c.is_func && !c.is_trap && c.n_params == 0) {
        return Err(ctx.error(rapid_vm::ext::Err::CallProc, format!("`{name}` is no procedure without parameters")));
    }
    let number = ctx.resources.interrupts.once(routine);
    let action = super::robot::Action::Interrupt(number);
    Ok(vec![super::robot::PathEvent { at: super::robot::At::Point, shift: 0.0, action }])
}

/// Gives the I/O system the outputs of path events whose time is now known: at their
/// time, or now when that has passed (the program came to the next move late).
// uncertain: an event whose time has passed is set at once, not at its exact time.
pub(crate) fn apply_due_events(ctx: &mut Ctx<'_>) -> Result<(), RapidError> {
    let due = std::mem::take(&mut ctx.resources.robot_mut().due);
    for (time, action) in due {
        match action {
            super::robot::Action::Set { signal: id, value } => {
                if time > ctx.time {
                    ctx.resources.io_mut().order_on_path(time, id, value);
                } else {
                    rapid_signals::order(ctx, |io, t| io.set(id, value, t))?;
                }
            }
            super::robot::Action::ZoneSet { signal: id, value } => {
                if time > ctx.time {
                    ctx.resources.io_mut().order_on_path(time, id, value);
                } else {
                    rapid_signals::order(ctx, |io, t| io.set_by_system(id, value, t))?;
                }
            }
            super::robot::Action::Interrupt(number) => ctx.resources.interrupts.schedule(time, number),
            super::robot::Action::Special(key) => super::trigg::defer(ctx, time, key),
        }
    }
    Ok(())
}

/// A robtarget's path pose (what linear and circular paths are planned in, see
/// `rapid_motion::plan::Mount`): the TCP in the robot base frame for a robot-held
/// tool; for a stationary tool the TCP in the held work object's (displaced) frame,
/// which is the robtarget itself.
fn tcp_in_base(
    ctx: &Ctx<'_>,
    chain: &rapid_motion::frames::FrameChain,
    target: &Value,
) -> Result<rapid_motion::Pose, RapidError> {
    let (pose, _) = data::robtarget(ctx, target)?;
    Ok(path_pose(chain, &pose))
}

/// The path pose of a robtarget pose (see [`tcp_in_base`]).
pub(super) fn path_pose(chain: &rapid_motion::frames::FrameChain, target: &rapid_motion::Pose) -> rapid_motion::Pose {
    if chain.stationary_tool {
        *target
    } else {
        chain.flange_goal(target) * chain.tframe
    }
}

/// A move request's work object frame for these frames: user frame · object frame.
pub(super) fn wobj_frame(chain: &rapid_motion::frames::FrameChain) -> rapid_motion::Pose {
    chain.uframe * chain.oframe
}

/// A move request's `tool` and `held_object` for these frames: the tool frame, or for
/// a stationary tool its TCP in the base frame and the held work object's frame
/// (user, object, displacement) in the flange frame.
pub(super) fn mount_of(chain: &rapid_motion::frames::FrameChain) -> (rapid_motion::Pose, Option<rapid_motion::Pose>) {
    if chain.stationary_tool {
        (chain.base.inverse() * chain.tframe, Some(chain.uframe * chain.oframe * chain.pdisp))
    } else {
        (chain.tframe, None)
    }
}

/// `MoveAbsJ`: joint interpolation to axis values (no displacement applies).
pub(crate) fn move_abs_j(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    abs_joint_move(ctx, args, &MOVE_ABS_J, Vec::new())
}

/// MoveAbsJ and TriggAbsJ.
pub(super) fn abs_joint_move(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    layout: &Layout,
    events: Vec<super::robot::PathEvent>,
) -> Res {
    require_motion_task(ctx)?;
    // A jointtarget's eax_a is a 7-axis arm's axis 7 itself.
    ctx.resources.robot_mut().next_axis7 = None;
    let chain = frames(ctx, args, layout, false)?;
    let mut joints = data::jointtarget(ctx, &ctx.value(&args[layout.to])?)?;
    if !moves_robot(ctx) {
        // A positioner's task: only the external axes move (`robax` is not used).
        joints = ctx.resources.robot_mut().end_joints();
    }
    if let Some(axis) = ctx.resources.robot_mut().kin.limit_violation(&joints) {
        return Err(motion_error(MotionError::JointLimit { axis }));
    }
    go_with(ctx, args, layout, Target::Joints(joints), chain, events)
}

/// `WaitRob [\InPos] | [\ZeroSpeed]`: waits until the robot stands still at the end of
/// its last move (traps of path interrupts run meanwhile, as during a move).
pub(crate) fn wait_rob(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let end = ctx.resources.robot_mut().flush();
    apply_due_events(ctx)?;
    wait_for_robot(ctx, end);
    Ok(None)
}

/// Where the move about to be given is programmed (for the event of a corner path
/// failure), and while a trace or report is recorded what it is (its instruction,
/// programmed point, zone, frames), for the outputs; nothing is allocated otherwise.
pub(super) fn note_facts(ctx: &mut Ctx<'_>, request: &MoveRequest, chain: &rapid_motion::frames::FrameChain) {
    use rapid_motion::Kinematics as _;
    let (instruction, file, span) = instruction_here(ctx);
    ctx.resources.robot_mut().next_place = Some((file, span));
    if ctx.resources.robot_mut().recorded.is_none() {
        return;
    }
    let robot = ctx.resources.robot_mut();
    let point = match request.target {
        Target::Joints(joints) => chain.tcp_in_world(&robot.kin.forward(&joints)),
        Target::Linear(to) | Target::Circular { to, .. } => chain.base * to,
    };
    robot.next_facts = Some(super::robot::MoveFacts {
        instruction,
        file,
        span,
        point,
        zone: if request.zone.is_stop() { 0.0 } else { request.zone.pzone_tcp },
        fine: request.zone.is_stop(),
        frames: *chain,
        start: 0.0,
        end: 0.0,
        passed: 0.0,
        zone_used: 0.0,
        corner_path_failure: false,
        corner: None,
    });
}

/// The built-in the running routine is calling and its statement: (name, file, span),
/// as the event log places what a built-in logs.
fn instruction_here(ctx: &Ctx<'_>) -> (&'static str, usize, rapid_syntax::Span) {
    ctx.instruction_here()
}
