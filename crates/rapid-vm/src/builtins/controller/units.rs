//! Tasks and mechanical units as the controller reports them (§1.17, §1.20):
//! GetTSPStatus, MotionPlannerNo, GetMecUnitName, GetServiceInfo. TaskIsActive and
//! TaskIsExecuting are in tasking.rs.
//!
//! The robot of the n-th motion task is ROB_n and its motion planner is number n, in
//! configuration order (a one-task run has T_ROB1, ROB_1, planner 1).

use super::super::{argname, present, tasking, Ctx};
use super::Res;
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

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
pub(crate) fn get_tsp_status(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let task = tasking::named_task(ctx, args)?;
    let status = match (task.normal, task.active) {
        (false, _) => TSP_STATUS_NOT_NORMAL_TASK,
        (true, true) => TSP_STATUS_ACT,
        (true, false) => TSP_STATUS_DEACT,
    };
    Ok(Some(Value::Num(status)))
}

/// The number (from 1) of the motion planner of the task's robot: its place among
/// the motion tasks; a task without a robot uses the planner of the motion task it is
/// connected to; 0 when the system has no motion task.
// uncertain: a task without a robot is taken to be connected to the first motion
// task (as GetTaskName \MecTaskNo does); the controller follows
// -UseMechanicalUnitGroup.
fn planner_no(ctx: &Ctx<'_>) -> usize {
    let tasking = &ctx.resources.tasking;
    let motion: Vec<&str> = tasking.shared.tasks.iter().filter(|t| t.motion).map(|t| t.name.as_str()).collect();
    let mine = motion.iter().position(|name| name.eq_ignore_ascii_case(tasking.name()));
    match (mine, motion.is_empty()) {
        (Some(index), _) => index + 1,
        (None, false) => 1,
        (None, true) => 0,
    }
}

/// `MotionPlannerNo()`: the number of the motion planner the task's movements use.
pub(crate) fn motion_planner_no(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Num(planner_no(ctx) as f32)))
}

/// The configured name of the mechanical unit passed for parameter `param`: the
/// mecunit data's name; ROB_ID stands for the task's own robot.
// uncertain: ROB_ID in a task without a robot is undefined on the controller; using
// it raises ERR_ARGVALERR here.
fn unit_name(ctx: &Ctx<'_>, param: usize) -> Result<String, RapidError> {
    let Some(name) = argname::original_name(ctx.chain, param) else {
        return Err(ctx.error(Err::ArgValue, "MechUnit must be a mecunit data object (ROB_1, ROB_ID ...)"));
    };
    if !name.eq_ignore_ascii_case("ROB_ID") {
        return Ok(name.to_string());
    }
    let tasking = &ctx.resources.tasking;
    let robots: Vec<&str> = tasking.shared.tasks.iter().filter(|t| t.robot).map(|t| t.name.as_str()).collect();
    match robots.iter().position(|name| name.eq_ignore_ascii_case(tasking.name())) {
        Some(index) => Ok(format!("ROB_{}", index + 1)),
        // A program run alone is T_ROB1's, with ROB_1.
        None if tasking.shared.tasks.is_empty() => Ok("ROB_1".to_owned()),
        None => Err(ctx.error(Err::ArgValue, "ROB_ID: this task controls no robot")),
    }
}

/// `GetMecUnitName(MechUnit)`: the mechanical unit's configured name ("ROB_1").
pub(crate) fn get_mec_unit_name(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Str(unit_name(ctx, 0)?.into())))
}

/// `GetServiceInfo(MechUnit [\DutyTimeCnt])`: service information of the unit. The
/// duty time counter is the time the unit has been in operation, in whole hours: the
/// virtual robot's motors are on from the start of the run, so it is the controller
/// time.
// uncertain: the manual does not show the text's form; we give the whole hours as
// digits ("2" after 2 h 10 min). Without \DutyTimeCnt no item is chosen:
// ERR_ARGVALERR, as GetSysInfo without a switch.
pub(crate) fn get_service_info(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    unit_name(ctx, 0)?;
    if !present(args.get(1)) {
        return Err(ctx.error(Err::ArgValue, "GetServiceInfo needs \\DutyTimeCnt"));
    }
    let hours = (ctx.time.max(0.0) / 3600.0).floor();
    Ok(Some(Value::Str(format!("{hours}").into())))
}
