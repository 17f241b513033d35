//! Tasks and mechanical units as the controller reports them (§1.17, §1.20):
//! GetTSPStatus, MotionPlannerNo, GetMecUnitName, GetServiceInfo. TaskIsActive and
//! TaskIsExecuting are in tasking.rs. (They read the tasks' kinds and the robots'
//! numbering, which this crate keeps; the robot reads [`planner_no`].)
//!
//! A motion task's robot is the ROB_n its mechanical unit group names, else the n-th
//! motion task's with a robot in configuration order (`SharedTasking::robot_number`);
//! its motion planner is number n (a one-task run has T_ROB1, ROB_1, planner 1).

use rapid_vm::ext::{native, present, Ctx, Err, Family, RapidError, Value};

use crate::tasking::{self, TaskingAccess};

type Res = Result<Option<Value>, RapidError>;

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("GetTSPStatus", get_tsp_status),
        native("MotionPlannerNo", motion_planner_no),
        native("GetMecUnitName", get_mec_unit_name),
        native("GetServiceInfo", get_service_info),
    ],
};

// The values of the tsp_status constants (catalogue data.rs).
const TSP_STATUS_NOT_NORMAL_TASK: f32 = 0.0;
const TSP_STATUS_DEACT: f32 = 1.0;
const TSP_STATUS_ACT: f32 = 3.0;

/// `GetTSPStatus(TaskRef | TaskName)`: the task's state in the Task Selection Panel:
/// TSP_STATUS_NOT_NORMAL_TASK for a STATIC or SEMISTATIC task, else TSP_STATUS_ACT
/// when selected, TSP_STATUS_DEACT when not. Every task of a `rapid run` system is
/// selected, and no task is deselected to run service routines, so
/// TSP_STATUS_DEACT_SERV_ROUT never comes. A task the system does not have is
/// ERR_TASKNAME.
fn get_tsp_status(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let task = tasking::named_task(ctx, args)?;
    let status = match (task.normal, task.active) {
        (false, _) => TSP_STATUS_NOT_NORMAL_TASK,
        (true, true) => TSP_STATUS_ACT,
        (true, false) => TSP_STATUS_DEACT,
    };
    Ok(Some(Value::Num(status)))
}

/// The number (from 1) of the motion planner of the task's robot: its robot's number
/// (ROB_n uses planner n); a motion task without a robot (a positioner's) the planners
/// after the robots', by its place among such tasks; a task without a robot uses the
/// planner of the motion task it is connected to; 0 when the system has no motion task.
// uncertain: the controller takes the planner from the mechanical unit group's
// -UseMotionPlanner, which RobotWare's configurations give rob1 motion_planner_1 and so
// on; a task that is no motion task is taken to be connected to the first motion task
// (as GetTaskName \MecTaskNo does); the controller follows -UseMechanicalUnitGroup.
pub fn planner_no(ctx: &Ctx<'_>) -> usize {
    let shared = &ctx.resources.tasking().shared;
    let mine = shared.tasks.iter().position(|t| t.name.eq_ignore_ascii_case(ctx.resources.tasks.name()));
    let motion = mine.filter(|&i| shared.tasks[i].motion).or_else(|| shared.tasks.iter().position(|t| t.motion));
    let Some(task) = motion else { return 0 };
    if let Some(n) = shared.robot_number(task) {
        return n;
    }
    let robots = shared.tasks.iter().filter(|t| t.robot).count();
    robots + shared.tasks[..=task].iter().filter(|t| t.motion && !t.robot).count()
}

/// `MotionPlannerNo()`: the number of the motion planner the task's movements use.
fn motion_planner_no(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Num(planner_no(ctx) as f32)))
}

/// The configured name of the mechanical unit passed for parameter `param`: the
/// mecunit data's name; ROB_ID stands for the task's own robot.
// uncertain: ROB_ID in a task without a robot is undefined on the controller; using
// it raises ERR_ARGVALERR here.
fn unit_name(ctx: &Ctx<'_>, param: usize) -> Result<String, RapidError> {
    let Some(name) = ctx.arg_name(param) else {
        return Err(ctx.error(Err::ArgValue, "MechUnit must be a mecunit data object (ROB_1, ROB_ID ...)"));
    };
    if !name.eq_ignore_ascii_case("ROB_ID") {
        return Ok(name.to_string());
    }
    let shared = &ctx.resources.tasking().shared;
    let mine = shared.tasks.iter().position(|t| t.name.eq_ignore_ascii_case(ctx.resources.tasks.name()));
    match mine.and_then(|task| shared.robot_number(task)) {
        Some(n) => Ok(format!("ROB_{n}")),
        // A program run alone is T_ROB1's, with ROB_1.
        None if shared.tasks.is_empty() => Ok("ROB_1".to_owned()),
        None => Err(ctx.error(Err::ArgValue, "ROB_ID: this task controls no robot")),
    }
}

/// `GetMecUnitName(MechUnit)`: the mechanical unit's configured name ("ROB_1").
fn get_mec_unit_name(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Str(unit_name(ctx, 0)?.into())))
}

/// `GetServiceInfo(MechUnit [\DutyTimeCnt])`: service information of the unit. The
/// duty time counter is the time the unit has been in operation, in whole hours: the
/// virtual robot's motors are on from the start of the run, so it is the controller
/// time.
// uncertain: the manual does not show the text's form; we give the whole hours as
// digits ("2" after 2 h 10 min). Without \DutyTimeCnt no item is chosen:
// ERR_ARGVALERR, as GetSysInfo without a switch.
fn get_service_info(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    unit_name(ctx, 0)?;
    if !present(args.get(1)) {
        return Err(ctx.error(Err::ArgValue, "GetServiceInfo needs \\DutyTimeCnt"));
    }
    let hours = (ctx.time.max(0.0) / 3600.0).floor();
    Ok(Some(Value::Str(format!("{hours}").into())))
}
