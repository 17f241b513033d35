//! Mechanical units (§1.8, §1.20): RobName, MaxRobSpeed, GetNextMechUnit,
//! IsMechUnitActive, ActUnit, DeactUnit, MechUnitLoad, ReadMotor.
//!
//! A `rapid run` system has one mechanical unit per motion task with a robot: the TCP
//! robot ROB_n its mechanical unit group names (else the n-th such task's, in
//! configuration order: `SharedTasking::robot_number`), with six axes and motion
//! planner n (a program run alone is T_ROB1 with ROB_1), and the external units the
//! configuration gives a motion task (`extax.rs`).
//! A mecunit argument is known by the data object passed (ROB_1, ROB_ID, a unit's
//! name), or by the unit number a GetNextMechUnit `\MecRef` wrote into it: robots are
//! 1, 2, …, this task's external units [`EXTERNAL_BASE`] + their index.

use crate::RobotResources;
use rapid_tasks::TaskingAccess;
use rapid_vm::ext::{present, Ctx, Err, Opaque, OpaqueState, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// Axes of every unit (the six of a robot arm).
pub(super) const ROBOT_AXES: usize = 6;

/// The unit number of this task's first external unit.
const EXTERNAL_BASE: usize = 1000;

/// The index among this task's external units of unit number `unit`.
pub(super) fn external_index(ctx: &Ctx<'_>, unit: usize) -> Option<usize> {
    let i = unit.checked_sub(EXTERNAL_BASE)?;
    (i < ctx.resources.robot().external.units.len()).then_some(i)
}

/// The name of unit number `unit` (ROB_n, this task's robot's own name, or an
/// external unit's).
fn unit_name(ctx: &Ctx<'_>, unit: usize) -> String {
    match external_index(ctx, unit) {
        Some(i) => ctx.resources.robot().external.units[i].unit.name.clone(),
        None => robot_name(ctx, unit),
    }
}

/// The name of robot number `n`: this task's robot's configured name (`ROB_L`) when it
/// has one, else `ROB_n`.
// uncertain: another task's robot named otherwise is still called ROB_n here.
fn robot_name(ctx: &Ctx<'_>, n: usize) -> String {
    match &ctx.resources.robot().name {
        Some(name) if own_unit(ctx) == Some(n) => name.clone(),
        _ => format!("ROB_{n}"),
    }
}

/// The robots of the system in the order of their numbers: (`n` of ROB_n, task number
/// from 1 among all tasks, task name). A program run alone is the motion task T_ROB1
/// with ROB_1.
fn robot_tasks(ctx: &Ctx<'_>) -> Vec<(usize, usize, String)> {
    let shared = &ctx.resources.tasking().shared;
    if shared.tasks.is_empty() {
        return vec![(1, 1, ctx.resources.tasks.name().to_string())];
    }
    shared.robots().into_iter().map(|(n, task)| (n, task + 1, shared.tasks[task].name.clone())).collect()
}

/// The unit number (from 1) of this task's robot, if it has one.
pub(super) fn own_unit(ctx: &Ctx<'_>) -> Option<usize> {
    let me = ctx.resources.tasks.name();
    robot_tasks(ctx).into_iter().find(|(_, _, name)| name.eq_ignore_ascii_case(me)).map(|(n, _, _)| n)
}

/// Whether the system has robot ROB_`n`.
fn has_robot(ctx: &Ctx<'_>, n: usize) -> bool {
    robot_tasks(ctx).iter().any(|(robot, _, _)| *robot == n)
}

/// The unit number of `ROB_n` (or of this task's robot by its own name), if the
/// system has it.
pub(super) fn unit_named(ctx: &Ctx<'_>, name: &str) -> Option<usize> {
    if ctx.resources.robot().name.as_deref().is_some_and(|own| own.eq_ignore_ascii_case(name)) {
        return own_unit(ctx);
    }
    let upper = name.to_ascii_uppercase();
    let n: usize = upper.strip_prefix("ROB_")?.parse().ok()?;
    has_robot(ctx, n).then_some(n)
}

/// The unit the mecunit argument `param` stands for (its number from 1).
// uncertain: a mecunit the system does not have (an unset variable, ROB_ID in a task
// without a robot) raises ERR_ARGVALERR; the controller refuses such programs at
// load time.
pub(super) fn unit_arg(ctx: &Ctx<'_>, args: &[Value], param: usize) -> Result<usize, RapidError> {
    if let Some(name) = ctx.arg_name(param) {
        if name.eq_ignore_ascii_case("ROB_ID") {
            return own_unit(ctx).ok_or_else(|| ctx.error(Err::ArgValue, "ROB_ID: this task controls no robot"));
        }
        if let Some(n) = unit_named(ctx, &name) {
            return Ok(n);
        }
        if let Some(i) = ctx.resources.robot().external.find(&name) {
            return Ok(EXTERNAL_BASE + i);
        }
        let others = &ctx.resources.robot().external.others;
        if let Some((unit, owner)) = others.iter().find(|(unit, _)| unit.eq_ignore_ascii_case(&name)) {
            return Err(RapidError::fatal(format!(
                "{unit} is a mechanical unit of task {owner}: using it from another task is not supported yet"
            )));
        }
    }
    let handle = match args.get(param).map(|a| ctx.value(a)).transpose()? {
        Some(Value::Opaque(opaque)) => match opaque.state {
            OpaqueState::Handle(h) => Some(h as usize),
            _ => None,
        },
        _ => None,
    };
    match handle {
        Some(n) if has_robot(ctx, n) || external_index(ctx, n).is_some() => Ok(n),
        _ => Err(ctx.error(Err::ArgValue, "the mechanical unit is not in the system")),
    }
}

/// The unit of an optional `\MecUnit` argument: this task's robot when absent.
pub(super) fn opt_unit_arg(ctx: &Ctx<'_>, args: &[Value], param: usize) -> Result<usize, RapidError> {
    if present(args.get(param)) {
        return unit_arg(ctx, args, param);
    }
    own_unit(ctx).ok_or_else(|| ctx.error(Err::ArgValue, "this task controls no robot: \\MecUnit is needed"))
}

/// Fails unless `unit` is this task's robot: the state of other tasks' robots is
/// theirs to keep.
pub(super) fn own_only(ctx: &Ctx<'_>, unit: usize) -> Result<(), RapidError> {
    if own_unit(ctx) == Some(unit) {
        return Ok(());
    }
    if external_index(ctx, unit).is_some() {
        return Err(RapidError::fatal(format!(
            "{} is an external unit: this instruction on external units is not supported yet",
            unit_name(ctx, unit)
        )));
    }
    Err(RapidError::fatal(format!(
        "ROB_{unit} belongs to another task: reading or changing it from here is not supported yet"
    )))
}

/// An axis number 1..=6 of a robot.
// uncertain: an axis the unit does not have raises ERR_ARGVALERR (some instructions
// document ERR_AXIS_PAR; those check with their own error).
pub(super) fn axis_arg(ctx: &Ctx<'_>, value: f64, err: Err) -> Result<usize, RapidError> {
    if value.fract() == 0.0 && (1.0..=ROBOT_AXES as f64).contains(&value) {
        return Ok(value as usize);
    }
    Err(ctx.error(err, format!("axis {value} is not an axis of the robot (1..6)")))
}

/// `RobName()`: the name of the TCP robot this task controls ("ROB_1"), or "" in a
/// task without a robot (manual: RobName).
pub(crate) fn rob_name(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let name = own_unit(ctx).map(|n| robot_name(ctx, n)).unwrap_or_default();
    Ok(Some(Value::Str(name.into())))
}

/// `MaxRobSpeed()`: the highest TCP speed of the robot type, mm/s.
pub(crate) fn max_rob_speed(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Num(ctx.resources.robot_mut().model.tcp_speed() as f32)))
}

/// `MaxRobReorientSpeed()`: the highest reorientation speed of the TCP (°/s): the v_ori
/// of vmax, the highest the planner is ever given.
// uncertain: ABB publishes no robot's reorientation maximum; this is the one the
// simulated robot reorients at most, so a program that builds its speeddata from it
// moves as fast as it can here.
pub(crate) fn max_rob_reorient_speed(_ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Num(rapid_motion::plan::SpeedData::VMAX.v_ori as f32)))
}

/// `GetNextMechUnit(ListNumber, UnitName [\MecRef] [\TCPRob] [\NoOfAxes] [\MecTaskNo]
/// [\MotPlanNo] [\Active] [\DriveModule] [\OKToDeact])`: the unit at ListNumber (from
/// 0: the robots by number, then this task's external units) with its data, ListNumber
/// moved on by one; FALSE (nothing written) after the last unit.
// uncertain: each robot is taken to sit on its own drive module (number n), and a TCP
// robot is never OK to deactivate (DeactUnit refuses it). External units are listed
// for the task that has them only, on its robot's motion planner and drive module.
pub(crate) fn get_next_mech_unit(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let list = ctx.num(&args[0])?;
    let robots = robot_tasks(ctx);
    let total = robots.len() + ctx.resources.robot_mut().external.units.len();
    if list < 0.0 || list.fract() != 0.0 || list >= total as f64 {
        return Ok(Some(Value::Bool(false)));
    }
    let at = list as usize;
    let (unit, facts) = match at.checked_sub(robots.len()) {
        None => {
            let n = robots[at].0;
            // A 4-axis palletizer has axes 1, 2, 3 and 6.
            // uncertain: another task's robot is taken to have six axes.
            let palletizer = own_unit(ctx) == Some(n) && ctx.resources.robot_mut().model.is_palletizer();
            (n, robot_facts(robots[at].1, n, if palletizer { 4 } else { ROBOT_AXES }))
        }
        Some(i) => (EXTERNAL_BASE + i, external_facts(ctx, i)),
    };
    ctx.store(&args[0], Value::Num((list + 1.0) as f32))?;
    ctx.store(&args[1], Value::Str(unit_name(ctx, unit).into()))?;
    if let Some(mec_ref) = args.get(2).filter(|a| present(Some(a))) {
        let (shell, _) = ctx.handle_arg(mec_ref, "a mecunit")?;
        let handle = Opaque { ty: shell.ty, state: OpaqueState::Handle(unit as u32) };
        ctx.store(mec_ref, Value::Opaque(Box::new(handle)))?;
    }
    for (arg, value) in args.iter().skip(3).zip(facts) {
        if present(Some(arg)) {
            ctx.store(arg, value)?;
        }
    }
    Ok(Some(Value::Bool(true)))
}

/// GetNextMechUnit's outputs for robot `n` of task number `task_no` with `axes` axes:
/// TCPRob, NoOfAxes, MecTaskNo, MotPlanNo, Active, DriveModule, OKToDeact.
fn robot_facts(task_no: usize, n: usize, axes: usize) -> [Value; 7] {
    [
        Value::Bool(true),
        Value::Num(axes as f32),
        Value::Num(task_no as f32),
        Value::Num(n as f32),
        Value::Bool(true),
        Value::Num(n as f32),
        Value::Bool(false),
    ]
}

/// GetNextMechUnit's outputs for this task's external unit `i`.
fn external_facts(ctx: &Ctx<'_>, i: usize) -> [Value; 7] {
    let state = &ctx.resources.robot().external.units[i];
    // The unit is this task's: its number in the system, and its motion planner (a
    // positioner's task has a planner of its own after the robots').
    let task_no = ctx.resources.tasks.index() + 1;
    let planner = rapid_tasks::planner_no(ctx).max(1);
    [
        Value::Bool(false),
        // A conveyor's unit has no axis the moves drive; its one axis is the conveyor's.
        Value::Num(state.unit.axes.len().max(1) as f32),
        Value::Num(task_no as f32),
        Value::Num(planner as f32),
        Value::Bool(state.active),
        Value::Num(planner as f32),
        Value::Bool(!state.unit.deactivation_forbidden),
    ]
}

/// `IsMechUnitActive(MechUnit)`: TRUE for a TCP robot (always active); an external
/// unit's state.
pub(crate) fn is_mech_unit_active(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let unit = unit_arg(ctx, args, 0)?;
    let active = external_index(ctx, unit).is_none_or(|i| ctx.resources.robot_mut().external.units[i].active);
    Ok(Some(Value::Bool(active)))
}

/// `ActUnit MechUnit`: the unit becomes active; a TCP robot already is. The robot
/// first stands still (a fly-by point before becomes a stop point, manual: ActUnit).
// uncertain: ActUnit of a TCP robot is taken to be allowed and change nothing.
pub(crate) fn act_unit(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let unit = unit_arg(ctx, args, 0)?;
    if let Some(i) = external_index(ctx, unit) {
        set_active(ctx, i, true);
    }
    Ok(None)
}

/// `DeactUnit MechUnit`: an external unit stops following the program (its axes stay
/// where they are). A TCP robot cannot be deactivated (manual: DeactUnit), nor a unit
/// configured with deactivation forbidden: execution stops.
pub(crate) fn deact_unit(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let unit = unit_arg(ctx, args, 0)?;
    let Some(i) = external_index(ctx, unit) else {
        return Err(RapidError::fatal(format!("DeactUnit: ROB_{unit} is a TCP robot, which cannot be deactivated")));
    };
    if ctx.resources.robot_mut().external.units[i].unit.deactivation_forbidden {
        return Err(RapidError::fatal(format!(
            "DeactUnit: {} is configured with deactivation forbidden",
            unit_name(ctx, unit)
        )));
    }
    set_active(ctx, i, false);
    Ok(None)
}

/// Activates or deactivates external unit `i` once the robot stands still.
fn set_active(ctx: &mut Ctx<'_>, i: usize, active: bool) {
    let end = ctx.resources.robot_mut().flush();
    ctx.resources.robot_mut().external.units[i].active = active;
    super::moves::wait_for_robot(ctx, end);
}

rapid_vm::ext::layout! {
    static MECH_UNIT_LOAD: MechUnitLoadArgs = "MechUnitLoad" { load: "Load" }
}

/// `MechUnitLoad MechUnit, AxisNo, Load`: the payload on an axis of an external unit
/// (kept with the unit; the simulated motion does not depend on loads). The robots'
/// payload is GripLoad's: execution stops for a TCP robot.
// uncertain: the controller's reaction to MechUnitLoad on a TCP robot is not public.
pub(crate) fn mech_unit_load(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let unit = unit_arg(ctx, args, 0)?;
    let Some(i) = external_index(ctx, unit) else {
        axis_arg(ctx, ctx.num(&args[1])?, Err::ArgValue)?;
        return Err(RapidError::fatal(format!(
            "MechUnitLoad: ROB_{unit} is a TCP robot; its payload is set with GripLoad"
        )));
    };
    let axis = ctx.num(&args[1])?;
    let axes = ctx.resources.robot_mut().external.units[i].unit.axes.len();
    if axis.fract() != 0.0 || !(1.0..=axes as f64).contains(&axis) {
        let name = unit_name(ctx, unit);
        return Err(ctx.error(Err::ArgValue, format!("axis {axis} is not an axis of {name} (1..{axes})")));
    }
    let mass = match ctx.value(&args[MECH_UNIT_LOAD.load])? {
        Value::Record(load) => match load.fields.first() {
            Some(Value::Num(mass)) => f64::from(*mass),
            _ => return Err(ctx.error(Err::ArgValue, "the load is no loaddata")),
        },
        _ => return Err(ctx.error(Err::ArgValue, "the load is no loaddata")),
    };
    if mass < 0.0 {
        return Err(ctx.error(Err::ArgValue, format!("the load's mass {mass} kg is negative")));
    }
    ctx.resources.robot_mut().external.units[i].loads.insert(axis as usize, mass);
    Ok(None)
}

/// `ReadMotor([\MecUnit,] Axis)`: the motor angle of an axis, radians.
// uncertain: ABB's gear ratios are not public; a ratio of 1 is used for every axis,
// so the motor angle is the axis angle in radians (also in GetMotorTorque).
pub(crate) fn read_motor(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let unit = opt_unit_arg(ctx, args, 0)?;
    own_only(ctx, unit)?;
    let axis = axis_arg(ctx, ctx.num(&args[1])?, Err::ArgValue)?;
    let now = ctx.time;
    let joints = ctx.resources.robot_mut().joints_at(now);
    Ok(Some(Value::Num(joints[axis - 1].to_radians() as f32)))
}
