//! Synchronized movement of several robots (MultiMove, manual §1.20 and §1.8):
//! SyncMoveOn, SyncMoveOff, SyncMoveUndo, IsSyncMoveOn, TasksInSync, and the
//! coordination of the move instructions that carry `\ID` while the tasks move
//! together.
//!
//! SyncMoveOn and SyncMoveOff are sync points of their task list, as WaitSyncTask is
//! (the robot first stands still: both are stop points). Between them every move
//! instruction carries `\ID`; the moves with the same ID in all tasks start together
//! and take the same time, the time the slowest of them needs: each robot's move is
//! given that time as if by `\T`.

use crate::RobotResources;
use rapid_motion::external::ExternalMove;
use rapid_motion::plan::{AccelLimits, MotionSettings, MoveRequest, Planner};
use rapid_tasks::{meet, sync_point, task_list, SharedTasking, SyncMode, TaskingAccess};
use rapid_vm::ext::{native, present, Ctx, Err, Family, RapidError, Record, StopKind, Value};

type Res = Result<Option<Value>, RapidError>;

/// How long a task waiting for the others' coordinated moves looks again when nothing
/// else wakes it (the controller wakes it when one of them arrives).
const IDLE_POLL: f64 = 3600.0;

/// What a move instruction does about synchronized movement.
pub(crate) enum Coordination {
    /// The task moves alone: plan the move as it is.
    Alone,
    /// The other tasks' moves of this ID are not there yet: the instruction runs again.
    Wait,
    /// Every task's move is there: take this many seconds.
    Time(f64),
}

/// The robot stands still before a stop-point instruction goes on: `false` (and a
/// wait) while it still moves.
pub(crate) fn robot_stands(ctx: &mut Ctx<'_>) -> Result<bool, RapidError> {
    let end = ctx.resources.robot_mut().flush();
    super::apply_due_events(ctx)?;
    if end > ctx.time {
        // The instruction looks again when the robot stands, or earlier when an
        // interrupt may come (its trap runs meanwhile, §1.11).
        let next = rapid_vm::ext::next_due(ctx).map_or(end, |due| due.min(end));
        ctx.wait = Some((next - ctx.time).max(1e-6));
        ctx.stop = StopKind::Repeat;
        return Ok(false);
    }
    Ok(true)
}

/// `SyncMoveOn SyncID, TaskList [\TimeOut]`: meets the tasks of the list, then they
/// move synchronized. ERR_SYNCMOVEON when they do not all come within TimeOut.
fn sync_move_on(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if ctx.resources.tasking().sync_move.is_some() {
        // uncertain: a second SyncMoveOn before SyncMoveOff stops execution.
        return Err(RapidError::fatal("SyncMoveOn: the task already moves synchronized (SyncMoveOff first)"));
    }
    let point = sync_point(ctx, 0)?;
    let list = task_list(ctx, &args[1])?;
    let timeout = ctx.opt_num(args.get(2))?;
    if !robot_stands(ctx)? {
        return Ok(None);
    }
    let timed_out = (Err::SyncMoveOn, "the other tasks did not reach SyncMoveOn within \\TimeOut");
    if !meet(ctx, &point, &list, timeout, timed_out)? {
        return Ok(None);
    }
    let me = ctx.resources.tasks.name().to_string();
    let mut tasking = ctx.resources.tasking_mut();
    tasking.shared.in_sync.retain(|t| !t.eq_ignore_ascii_case(&me));
    tasking.shared.in_sync.push(me.clone());
    tasking.shared.epoch += 1;
    tasking.sync_move = Some(SyncMode { task: me, point, members: list, suspended: false });
    Ok(None)
}

/// `SyncMoveOff SyncID [\TimeOut]`: meets the tasks moving synchronized with this one,
/// then each moves on its own. ERR_SYNCMOVEOFF when they do not all come in time.
fn sync_move_off(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let Some(mode) = ctx.resources.tasking().sync_move.clone() else {
        // uncertain: SyncMoveOff outside synchronized movement stops execution.
        return Err(RapidError::fatal("SyncMoveOff: the task does not move synchronized (no SyncMoveOn)"));
    };
    let point = sync_point(ctx, 0)?;
    let timeout = ctx.opt_num(args.get(1))?;
    if !robot_stands(ctx)? {
        return Ok(None);
    }
    let timed_out = (Err::SyncMoveOff, "the other tasks did not reach SyncMoveOff within \\TimeOut");
    if !meet(ctx, &point, &mode.members, timeout, timed_out)? {
        return Ok(None);
    }
    leave(ctx);
    Ok(None)
}

/// `SyncMoveUndo`: the task moves on its own at once, without meeting the others
/// (in ERROR handlers, UNDO and at PP to Main).
fn sync_move_undo(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    leave(ctx);
    Ok(None)
}

/// Ends the task's synchronized movement.
fn leave(ctx: &mut Ctx<'_>) {
    let me = ctx.resources.tasks.name().to_string();
    let mut tasking = ctx.resources.tasking_mut();
    if let Some(mode) = tasking.sync_move.take() {
        if let Some(meet) = tasking.shared.move_meets.get_mut(&mode.point) {
            meet.entries.retain(|(t, _, _)| !t.eq_ignore_ascii_case(&me));
        }
    }
    tasking.move_round = None;
    tasking.shared.in_sync.retain(|t| !t.eq_ignore_ascii_case(&me));
    tasking.shared.epoch += 1;
    // The robot no longer follows another task's unit: it stands where it is when that
    // unit moves again.
    super::stop_following_other_tasks(ctx);
}

/// `IsSyncMoveOn()`: whether the task moves synchronized (not while suspended).
// uncertain: a suspended synchronized movement answers FALSE.
fn is_sync_move_on(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Bool(ctx.resources.tasking().sync_move.as_ref().is_some_and(|m| !m.suspended))))
}

/// `SyncMoveSuspend`: on the StorePath level (path level 2) the task moves on its own,
/// without `\ID`, until SyncMoveResume.
// uncertain: outside synchronized movement or on path level 1 it stops execution.
fn sync_move_suspend(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    set_suspended(ctx, true, "SyncMoveSuspend")
}

/// `SyncMoveResume`: back to synchronized movement on the StorePath level.
fn sync_move_resume(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    set_suspended(ctx, false, "SyncMoveResume")
}

fn set_suspended(ctx: &mut Ctx<'_>, suspended: bool, what: &str) -> Res {
    if ctx.resources.robot_mut().stored.is_none() {
        return Err(RapidError::fatal(format!("{what} is only allowed on the StorePath level (after StorePath)")));
    }
    let mut tasking = ctx.resources.tasking_mut();
    let Some(mode) = tasking.sync_move.as_mut() else {
        return Err(RapidError::fatal(format!("{what}: the task does not move synchronized (no SyncMoveOn)")));
    };
    mode.suspended = suspended;
    Ok(None)
}

/// `TasksInSync(TaskList)`: how many tasks move synchronized now; their names fill
/// the list from the start, the rest of it is emptied.
fn tasks_in_sync(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let names = ctx.resources.tasking().shared.in_sync.clone();
    if let Value::Array(mut array) = ctx.value(&args[0])? {
        let mut given = names.iter();
        for elem in &mut array.elems {
            if let Value::Record(record) = elem {
                let record: &mut Record = std::rc::Rc::make_mut(record);
                if let Some(name) = record.fields.first_mut() {
                    *name = Value::Str(given.next().map_or("", String::as_str).into());
                }
            }
        }
        ctx.store(&args[0], Value::Array(array))?;
    }
    Ok(Some(Value::Num(names.len() as f32)))
}

/// A move instruction's part in synchronized movement: alone outside it; inside it
/// the move must carry `\ID` (`id`), and waits until the moves of that ID of every
/// task of the group are given, then takes the time the slowest needs.
pub(crate) fn coordinate(
    ctx: &mut Ctx<'_>,
    id: Option<&Value>,
    request: &MoveRequest,
    settings: &MotionSettings,
    external: Option<&ExternalMove>,
) -> Result<Coordination, RapidError> {
    let Some(mode) = ctx.resources.tasking().sync_move.clone().filter(|m| !m.suspended) else {
        // uncertain: `\ID` outside synchronized movement (or while it is suspended) is
        // ignored.
        return Ok(Coordination::Alone);
    };
    if !present(id) {
        return Err(RapidError::fatal("a move instruction in synchronized movement (after SyncMoveOn) needs \\ID"));
    }
    let id = ctx.num(id.unwrap_or(&Value::Absent))?;
    let alone = match settings.move_time {
        Some(t) => t,
        None => time_alone(ctx, request, settings, external)?,
    };
    let me = ctx.resources.tasks.name().to_string();
    let rapid_tasks::TaskingMut { shared, own } = ctx.resources.tasking_mut();
    let meeting = shared.move_meets.entry(mode.point.clone()).or_default();
    let round = match own.move_round {
        Some(round) => round,
        None => {
            meeting.entries.retain(|(t, _, _)| !t.eq_ignore_ascii_case(&me));
            meeting.entries.push((me, id, alone));
            own.move_round = Some(meeting.round);
            shared.epoch += 1;
            meeting.round
        }
    };
    complete_if_all_given(shared, &mode);
    let meeting = shared.move_meets.entry(mode.point.clone()).or_default();
    match &meeting.last {
        Some((done, outcome)) if *done == round => {
            let outcome = outcome.clone();
            own.move_round = None;
            outcome.map(Coordination::Time).map_err(RapidError::fatal)
        }
        _ => {
            ctx.wait = Some(IDLE_POLL);
            ctx.stop = StopKind::Repeat;
            Ok(Coordination::Wait)
        }
    }
}

/// Ends a round of coordinated moves once every executing task of the group gave its
/// move: the common time is the longest; different IDs are an error for all.
fn complete_if_all_given(shared: &mut SharedTasking, mode: &SyncMode) {
    let executing = |name: &String| shared.tasks.iter().any(|t| t.name.eq_ignore_ascii_case(name) && t.executing);
    let members: Vec<&String> = mode.members.iter().filter(|m| executing(m)).collect();
    let Some(meeting) = shared.move_meets.get_mut(&mode.point) else { return };
    let all = members.iter().all(|m| meeting.entries.iter().any(|(t, _, _)| t.eq_ignore_ascii_case(m)));
    if !all || meeting.entries.is_empty() {
        return;
    }
    let first_id = meeting.entries[0].1;
    let outcome = if meeting.entries.iter().all(|(_, id, _)| *id == first_id) {
        Ok(meeting.entries.iter().map(|(_, _, t)| *t).fold(0.0, f64::max))
    } else {
        let ids: Vec<String> = meeting.entries.iter().map(|(t, id, _)| format!("{t} \\ID:={id}")).collect();
        Err(format!("synchronized moves with different \\ID values: {}", ids.join(", ")))
    };
    meeting.last = Some((meeting.round, outcome));
    meeting.round += 1;
    meeting.entries.clear();
    shared.epoch += 1;
}

/// The time the robot (with its external axes' part, `external`) would take for
/// `request` on its own, from where its last move ends to standing still at the point
/// (a stop-to-stop move).
// uncertain: coordinated moves are timed stop to stop; corner paths at fly-by points
// shorten each robot's move a little, as they do any timed move.
fn time_alone(
    ctx: &Ctx<'_>,
    request: &MoveRequest,
    settings: &MotionSettings,
    external: Option<&ExternalMove>,
) -> Result<f64, RapidError> {
    let robot = ctx.resources.robot();
    let mut planner = Planner::new(robot.end_joints(), AccelLimits::nominal(&robot.model.max_speeds));
    planner.set_settings(*settings);
    planner.set_eax(external.map(|ext| ext.from));
    let request = MoveRequest { zone: rapid_motion::plan::ZoneData::FINE, ..*request };
    planner.push_with(&robot.kin, &request, external).map_err(super::motion_error)?;
    Ok(planner.flush().map_or(0.0, |m| m.zone_entry - m.start))
}

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("SyncMoveOn", sync_move_on),
        native("SyncMoveOff", sync_move_off),
        native("SyncMoveUndo", sync_move_undo),
        native("SyncMoveSuspend", sync_move_suspend),
        native("SyncMoveResume", sync_move_resume),
        native("IsSyncMoveOn", is_sync_move_on),
        native("TasksInSync", tasks_in_sync),
    ],
};
