//! Multitasking (§1.20) as a task sees it: WaitSyncTask, TestAndSet, WaitTestAndSet,
//! GetTaskName, TaskRunMec, TaskRunRob, TaskIsActive, TaskIsExecuting, IsSyncMoveOn,
//! TasksInSync.
//!
//! What the tasks of a controller share (the task list, the sync points) is a
//! [`SharedTasking`] the controller lends to whichever task runs (in `Shared::lent`,
//! which `Vm::exchange_shared` swaps whole with the task's `Resources::lent`); a task
//! alone has the one-task list of `Default`. Which task this is, the task names and the requests to the
//! controller are the interpreter core's (`rapid_vm::ext::TaskPlace`). Waits here
//! are re-checked (`StopKind::Repeat`): the controller wakes a waiting task whenever
//! another task changes the shared state, so nothing depends on a polling period.

use std::sync::Arc;

use rapid_vm::ext::{
    call_site, native, next_due, present, stands_still, Ctx, Err, Family, RapidError, Resources, StopKind, Value,
};
use rustc_hash::FxHashMap;

type Res = Result<Option<Value>, RapidError>;

/// How long a sync wait without \TimeOut sleeps before looking again when nothing
/// wakes it: only a bound, as the controller wakes waiting tasks on every change.
const IDLE_POLL: f64 = 3600.0;

/// One task of the system, as every task sees it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TaskInfo {
    pub name: String,
    /// Runs motion instructions (`-MotionTask`): TaskRunMec.
    pub motion: bool,
    /// A motion task that moves a robot with a TCP (TaskRunRob); a positioner's task
    /// moves external units only.
    pub robot: bool,
    /// A NORMAL task (not STATIC or SEMISTATIC): GetTSPStatus.
    pub normal: bool,
    /// Selected in the task selection panel (TaskIsActive); every configured task is.
    pub active: bool,
    /// Executing now (started, not stopped or ended): TaskIsExecuting.
    pub executing: bool,
    /// Its RAPID Message Queue (none by default).
    pub rmq: crate::rmq::RmqConfig,
    /// A task that is no motion task: the motion task whose mechanical unit group it
    /// uses, whose robot it reads (CJointT, CRobT).
    pub robot_of: Option<String>,
}

/// A sync point of WaitSyncTask: which tasks have arrived in the current round.
#[derive(Debug, Clone, Default)]
struct SyncPoint {
    /// Completed rounds; a waiting task passes once the round it arrived in is over.
    round: u64,
    arrived: Vec<String>,
}

/// A task in synchronized movement: its SyncMoveOn's sync point and task list (the
/// robot's SyncMoveOn sets it; PP to Main ends it).
#[derive(Debug, Clone, PartialEq)]
pub struct SyncMode {
    /// The task in synchronized movement (PP to Main takes it out of the shared list).
    pub task: String,
    pub point: String,
    pub members: Vec<String>,
    /// SyncMoveSuspend: on the StorePath level the task moves on its own until
    /// SyncMoveResume.
    pub suspended: bool,
}

/// The coordinated move the tasks of one synchronized group are meeting at (kept by
/// the robot's move instructions, in the state the tasks share).
#[derive(Debug, Clone, Default)]
pub struct MoveMeet {
    pub round: u64,
    /// (task, `\ID`, the time its robot would need alone) of the moves given so far.
    pub entries: Vec<(String, f64, f64)>,
    /// The last round completed: its number and the common time, or why there is none.
    pub last: Option<(u64, Result<f64, String>)>,
}

/// The multitasking state all tasks share.
#[derive(Debug, Clone)]
pub struct SharedTasking {
    pub tasks: Vec<TaskInfo>,
    sync: FxHashMap<String, SyncPoint>,
    /// Bumped on every change a waiting task could be waiting for (the controller
    /// adds it to the core's `SharedTasks::epoch`).
    pub epoch: u64,
    /// The names of the tool, work object and payload each task activated, by task
    /// name in lower case (GetSysData \TaskName from another task); a task not listed
    /// uses tool0, wobj0 and load0 (`motion::sysdata`).
    pub sysdata: FxHashMap<String, [Option<Arc<str>>; 3]>,
    /// The tasks in synchronized movement (SyncMoveOn … SyncMoveOff), by name.
    pub in_sync: Vec<String>,
    /// The coordinated moves under way, by the sync point of their SyncMoveOn.
    pub move_meets: FxHashMap<String, MoveMeet>,
    /// The robot (`n` of ROB_n) each task moves, by task index, when the configuration
    /// numbers the robots (`MECHANICAL_UNIT_GROUP -Robot`); empty: the n-th task with a
    /// robot moves ROB_n. Kept beside `tasks` (not in [`TaskInfo`]) because the
    /// controller builds those from its task specs.
    robot_numbers: Vec<Option<usize>>,
}

impl Default for SharedTasking {
    /// A system of one task, T_ROB1, moving the robot.
    fn default() -> Self {
        let rmq = crate::rmq::RmqConfig::default();
        let t_rob1 = TaskInfo {
            name: "T_ROB1".into(),
            motion: true,
            robot: true,
            normal: true,
            active: true,
            executing: true,
            rmq,
            robot_of: None,
        };
        SharedTasking::new(vec![t_rob1])
    }
}

impl SharedTasking {
    /// The system's tasks, in configuration order.
    pub fn new(tasks: Vec<TaskInfo>) -> SharedTasking {
        SharedTasking {
            tasks,
            sync: FxHashMap::default(),
            epoch: 0,
            sysdata: FxHashMap::default(),
            in_sync: Vec::new(),
            move_meets: FxHashMap::default(),
            robot_numbers: Vec::new(),
        }
    }

    /// Numbers the robots as the configuration does: `numbers[i]` is the `n` of the
    /// ROB_n task `i` moves. Fails, changing nothing, unless it gives each task with a
    /// robot (and no other) its own number from 1.
    pub fn number_robots(&mut self, numbers: Vec<Option<usize>>) -> Result<(), String> {
        if numbers.len() != self.tasks.len() {
            return Err(format!("{} robot numbers for {} tasks", numbers.len(), self.tasks.len()));
        }
        let mut seen = Vec::new();
        for (task, n) in self.tasks.iter().zip(&numbers) {
            match n {
                Some(0) => return Err(format!("task {}: robots are numbered from 1", task.name)),
                Some(n) if seen.contains(n) => return Err(format!("ROB_{n} is given to two tasks")),
                Some(n) if task.robot => seen.push(*n),
                None if !task.robot => {}
                _ => return Err(format!("task {}: a robot number goes with a robot", task.name)),
            }
        }
        self.robot_numbers = numbers;
        Ok(())
    }

    /// The `n` of the robot ROB_n task `task` (an index) moves; `None` for a task without
    /// a robot.
    pub fn robot_number(&self, task: usize) -> Option<usize> {
        if !self.tasks.get(task)?.robot {
            return None;
        }
        match self.robot_numbers.get(task) {
            Some(n) => *n,
            None => Some(self.tasks[..task].iter().filter(|t| t.robot).count() + 1),
        }
    }

    /// The robots of the system in the order of their numbers: (`n` of ROB_n, index of
    /// the task that moves it).
    pub fn robots(&self) -> Vec<(usize, usize)> {
        let mut robots: Vec<(usize, usize)> =
            (0..self.tasks.len()).filter_map(|task| Some((self.robot_number(task)?, task))).collect();
        robots.sort_unstable();
        robots
    }

    /// The task of this name (any letter case).
    pub fn task(&self, name: &str) -> Option<&TaskInfo> {
        self.tasks.iter().find(|t| t.name.eq_ignore_ascii_case(name))
    }

    /// Marks a task executing or not (the controller, as tasks start and end).
    pub fn set_executing(&mut self, name: &str, executing: bool) {
        if let Some(task) = self.tasks.iter_mut().find(|t| t.name.eq_ignore_ascii_case(name)) {
            if task.executing != executing {
                task.executing = executing;
                self.epoch += 1;
            }
        }
    }
}

/// The task's own side (in its extension slot): its shared view, the sync wait under
/// way. Who it is is the core's (`Resources::tasks`).
#[derive(Debug, Clone, Default)]
pub struct TaskingState {
    /// The WaitSyncTask under way: (sync point, round it arrived in, started at,
    /// call depth, pc).
    waiting: Option<(String, u64, f64, usize, u32)>,
    /// Synchronized movement (SyncMoveOn): its sync point and the tasks moving together.
    pub sync_move: Option<SyncMode>,
    /// The coordinated move this task waits at: the round of its meeting it joined.
    pub move_round: Option<u64>,
}

impl TaskingState {
    /// When the WaitSyncTask under way began, if one is.
    pub fn sync_wait_started(&self) -> Option<f64> {
        self.waiting.as_ref().map(|w| w.2)
    }

    /// Forgets a wait under way (PP to Main).
    pub(crate) fn end_waits(&mut self, shared: &mut SharedTasking) {
        self.waiting = None;
        self.move_round = None;
        // PP to Main ends synchronized movement, as SyncMoveUndo does.
        if let Some(mode) = self.sync_move.take() {
            shared.in_sync.retain(|t| !t.eq_ignore_ascii_case(&mode.task));
        }
    }
}

impl rapid_vm::ext::TaskState for TaskingState {
    fn close_all_lent(&mut self, lent: &mut rapid_vm::ext::Extensions) {
        self.end_waits(lent.get_or_default::<SharedTasking>());
    }
}

impl rapid_vm::ext::TaskState for SharedTasking {}

/// A task's multitasking state as it reads it: its own ([`TaskingState`], through
/// `Deref`) and what the tasks share (`shared`, lent to the task while it runs).
pub struct Tasking<'a> {
    pub shared: &'a SharedTasking,
    pub own: &'a TaskingState,
}

impl std::ops::Deref for Tasking<'_> {
    type Target = TaskingState;
    fn deref(&self) -> &TaskingState {
        self.own
    }
}

/// [`Tasking`] to change.
pub struct TaskingMut<'a> {
    pub shared: &'a mut SharedTasking,
    pub own: &'a mut TaskingState,
}

impl std::ops::Deref for TaskingMut<'_> {
    type Target = TaskingState;
    fn deref(&self) -> &TaskingState {
        self.own
    }
}

impl std::ops::DerefMut for TaskingMut<'_> {
    fn deref_mut(&mut self) -> &mut TaskingState {
        self.own
    }
}

/// A task without the tasks extension's state reads this (one task, T_ROB1).
static ALONE: std::sync::LazyLock<(TaskingState, SharedTasking)> = std::sync::LazyLock::new(Default::default);

/// The task's multitasking state: its own in its extension slot
/// (`Resources::extensions`), the shared part in the state lent to it
/// (`Resources::lent`, which the core swaps whole with the controller's).
pub trait TaskingAccess {
    /// The task's state (that of a task alone when it has none yet).
    fn tasking(&self) -> Tasking<'_>;
    /// The task's state to change (put in at its default first).
    fn tasking_mut(&mut self) -> TaskingMut<'_>;
}

impl TaskingAccess for Resources {
    #[inline]
    fn tasking(&self) -> Tasking<'_> {
        let own = self.extensions.get::<TaskingState>().unwrap_or(&ALONE.0);
        Tasking { shared: self.lent.get::<SharedTasking>().unwrap_or(&ALONE.1), own }
    }

    #[inline]
    fn tasking_mut(&mut self) -> TaskingMut<'_> {
        let own = self.extensions.get_or_default::<TaskingState>();
        TaskingMut { shared: self.lent.get_or_default::<SharedTasking>(), own }
    }
}

/// The controller's shared multitasking state (in `Shared::lent`).
pub trait SharedTaskingAccess {
    /// The shared state (a system of one task when there is none yet).
    fn tasking(&self) -> &SharedTasking;
    /// The shared state to change (put in at its default first).
    fn tasking_mut(&mut self) -> &mut SharedTasking;
}

impl SharedTaskingAccess for rapid_vm::ext::Shared {
    #[inline]
    fn tasking(&self) -> &SharedTasking {
        self.lent.get::<SharedTasking>().unwrap_or(&ALONE.1)
    }

    fn tasking_mut(&mut self) -> &mut SharedTasking {
        self.lent.get_or_default::<SharedTasking>()
    }
}

rapid_vm::ext::layout! {
    static WAIT_SYNC_TASK: WaitSyncTaskArgs = "WaitSyncTask" {
        in_pos: "InPos", sync_id: "SyncID", task_list: "TaskList", time_out: "TimeOut",
    }
}

/// `WaitSyncTask [\InPos] SyncID, TaskList [\TimeOut]`: waits until every task of the
/// list has reached the sync point of this name (the syncident's data name, the same
/// in every task). Tasks of the list that are not executing are not waited for. With
/// `\InPos` the task's robot first stands still at the end of its last move (a fly-by
/// point becomes a stop point), as before a positioner moves the object it works on.
// uncertain: a task in the list the system does not have raises ERR_TASKNAME.
// uncertain: `\InPos` in a task that moves no robot (no motion task) waits for nothing.
fn wait_sync_task(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *WAIT_SYNC_TASK;
    let point = sync_point(ctx, at.sync_id)?;
    let list = task_list(ctx, &args[at.task_list])?;
    let timeout = ctx.opt_num(args.get(at.time_out))?;
    if present(args.get(at.in_pos)) && !stands_still(ctx)? {
        return Ok(None);
    }
    meet(
        ctx,
        &point,
        &list,
        timeout,
        (Err::WaitSyncTask, "the other tasks did not reach the sync point within \\TimeOut"),
    )?;
    Ok(None)
}

/// The name of the syncident argument at `index` (its identity across tasks).
pub fn sync_point(ctx: &Ctx<'_>, index: usize) -> Result<String, RapidError> {
    match ctx.arg_name(index) {
        Some(point) => Ok(point.to_ascii_lowercase()),
        None => Err(ctx.error(Err::ArgValue, "the sync point must be a syncident variable")),
    }
}

/// Meets the tasks of `list` at sync point `point` (WaitSyncTask, SyncMoveOn,
/// SyncMoveOff): `true` once every executing task of the list has arrived; `false`
/// while the task waits (the instruction runs again). Past `timeout` seconds the
/// error `on_timeout` names.
pub fn meet(
    ctx: &mut Ctx<'_>,
    point: &str,
    list: &[String],
    timeout: Option<f64>,
    on_timeout: (Err, &str),
) -> Result<bool, RapidError> {
    let me = ctx.resources.tasks.name().to_string();
    for name in list {
        if ctx.resources.tasking().shared.task(name).is_none() {
            return Err(ctx.error(Err::TaskName, format!("the system has no task `{name}`")));
        }
    }
    let here = call_site(ctx);
    let now = ctx.time;
    let mut tasking = ctx.resources.tasking_mut();
    let waiting = tasking.waiting.clone().filter(|w| w.0 == point && (w.3, w.4) == here);
    let (round, started) = match waiting {
        Some((_, round, started, _, _)) => (round, started),
        None => {
            let sync = tasking.shared.sync.entry(point.to_string()).or_default();
            if !sync.arrived.iter().any(|t| t.eq_ignore_ascii_case(&me)) {
                sync.arrived.push(me.clone());
            }
            tasking.shared.epoch += 1;
            (sync.round, now)
        }
    };
    complete_round_if_all_arrived(tasking.shared, point, list);
    if tasking.shared.sync.get(point).is_some_and(|s| s.round > round) {
        tasking.waiting = None;
        return Ok(true);
    }
    let deadline = timeout.map(|t| started + t);
    if deadline.is_some_and(|d| now >= d) {
        tasking.waiting = None;
        if let Some(sync) = tasking.shared.sync.get_mut(point) {
            sync.arrived.retain(|t| !t.eq_ignore_ascii_case(&me));
        }
        return Err(ctx.error(on_timeout.0, on_timeout.1));
    }
    tasking.waiting = Some((point.to_string(), round, started, here.0, here.1));
    let next = [deadline, next_due(ctx)].into_iter().flatten().min_by(f64::total_cmp);
    ctx.wait = Some(next.map_or(IDLE_POLL, |t| (t - now).max(1e-6)));
    ctx.stop = StopKind::Repeat;
    Ok(false)
}

/// Ends the round of a sync point once every executing task of the list is there.
fn complete_round_if_all_arrived(shared: &mut SharedTasking, point: &str, list: &[String]) {
    let Some(sync) = shared.sync.get(point) else { return };
    let all_there = list.iter().all(|name| {
        let executing = shared.tasks.iter().any(|t| t.name.eq_ignore_ascii_case(name) && t.executing);
        !executing || sync.arrived.iter().any(|a| a.eq_ignore_ascii_case(name))
    });
    if all_there {
        if let Some(sync) = shared.sync.get_mut(point) {
            sync.round += 1;
            sync.arrived.clear();
        }
        shared.epoch += 1;
    }
}

/// The task names of a `tasks` array (empty names are skipped).
pub fn task_list(ctx: &Ctx<'_>, arg: &Value) -> Result<Vec<String>, RapidError> {
    let Value::Array(array) = ctx.value(arg)? else {
        return Err(ctx.error(Err::ArgValue, "the task list must be an array of tasks"));
    };
    let names = array.elems.iter().filter_map(|elem| match elem {
        Value::Record(record) => match record.fields.first() {
            Some(Value::Str(name)) if !name.is_empty() => Some(name.to_string()),
            _ => None,
        },
        _ => None,
    });
    Ok(names.collect())
}

/// `TestAndSet(Object)`: takes the semaphore if it is free (FALSE): sets it and
/// returns TRUE; otherwise FALSE. Tasks run one instruction at a time, so the test and
/// the set are one step no other task can come between.
fn test_and_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let taken = matches!(ctx.value(&args[0])?, Value::Bool(true));
    if taken {
        return Ok(Some(Value::Bool(false)));
    }
    ctx.store(&args[0], Value::Bool(true))?;
    ctx.resources.tasking_mut().shared.epoch += 1;
    Ok(Some(Value::Bool(true)))
}

/// `WaitTestAndSet Object`: waits until the semaphore is free, then takes it.
fn wait_test_and_set(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    if let Some(Value::Bool(true)) = test_and_set(ctx, args)? {
        return Ok(None);
    }
    let next = next_due(ctx);
    ctx.wait = Some(next.map_or(IDLE_POLL, |t| (t - ctx.time).max(1e-6)));
    ctx.stop = StopKind::Repeat;
    Ok(None)
}

/// `GetTaskName([\TaskNo] | [\MecTaskNo])`: the task's name; `\TaskNo` also gives its
/// number; `\MecTaskNo` gives the name and number of the motion task it is
/// connected to (itself when it is one).
// uncertain: a task that is no motion task is taken to be connected to the first
// motion task of the system (the controller follows -UseMechanicalUnitGroup).
fn get_task_name(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let tasking = ctx.resources.tasking();
    let place = &ctx.resources.tasks;
    if present(args.get(1)) {
        let me = place.index() + 1;
        let motion = match tasking.shared.tasks.get(me - 1) {
            Some(task) if task.motion => Some(me),
            _ => tasking.shared.tasks.iter().position(|t| t.motion).map(|i| i + 1),
        };
        let Some(number) = motion else {
            return Err(ctx.error(Err::TaskName, "the system has no motion task"));
        };
        let name = tasking.shared.tasks[number - 1].name.clone();
        ctx.store(&args[1], Value::Num(number as f32))?;
        return Ok(Some(Value::Str(name.into())));
    }
    let (name, number) = (place.name().to_string(), place.index() + 1);
    if present(args.first()) {
        ctx.store(&args[0], Value::Num(number as f32))?;
    }
    Ok(Some(Value::Str(name.into())))
}

/// This task's entry in the system's task list.
pub fn my_task<'c>(ctx: &'c Ctx<'_>) -> Option<&'c TaskInfo> {
    ctx.resources.tasking().shared.task(ctx.resources.tasks.name())
}

/// `TaskRunRob()`: the task controls a robot with a TCP (it is a motion task).
fn task_run_rob(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Bool(my_task(ctx).is_some_and(|t| t.robot))))
}

/// `TaskRunMec()`: the task controls a mechanical unit (a robot, or only external units
/// as a positioner's task does): every motion task.
fn task_run_mec(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Bool(my_task(ctx).is_some_and(|t| t.motion))))
}

/// The task a `taskid | string` argument pair names: a taskid by its data name
/// (`T_ROB2Id` is T_ROB2), a string as written.
pub fn named_task(ctx: &Ctx<'_>, args: &[Value]) -> Result<TaskInfo, RapidError> {
    named_task_at(ctx, args, 0)
}

/// [`named_task`] for the `taskid | string` pair at parameters `first`, `first + 1`
/// (the core finds the task by name: `rapid_vm::ext::task_named`).
pub(crate) fn named_task_at(ctx: &Ctx<'_>, args: &[Value], first: usize) -> Result<TaskInfo, RapidError> {
    let index = rapid_vm::ext::task_named(ctx, args, first)?;
    let name = &ctx.resources.tasks.shared.names[index];
    let task = ctx.resources.tasking().shared.task(name).cloned();
    task.ok_or_else(|| ctx.error(Err::TaskName, format!("the system has no task `{name}`")))
}

/// `TaskIsActive(TaskRef | TaskName)`: the task is selected in the task selection
/// panel; every task of the configuration is, here.
fn task_is_active(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(Some(Value::Bool(named_task(ctx, args)?.active)))
}

/// `TaskIsExecuting(TaskRef | TaskName)`: the task is running (not stopped or ended).
fn task_is_executing(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(Some(Value::Bool(named_task(ctx, args)?.executing)))
}

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("WaitSyncTask", wait_sync_task),
        native("TestAndSet", test_and_set),
        native("WaitTestAndSet", wait_test_and_set),
        native("GetTaskName", get_task_name),
        native("TaskRunRob", task_run_rob),
        native("TaskRunMec", task_run_mec),
        native("TaskIsActive", task_is_active),
        native("TaskIsExecuting", task_is_executing),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    fn task(name: &str, robot: bool) -> TaskInfo {
        let rmq = crate::rmq::RmqConfig::default();
        let (motion, normal, active, executing, robot_of) = (true, true, true, true, None);
        TaskInfo { name: name.into(), motion, robot, normal, active, executing, rmq, robot_of }
    }

    /// PP to Main (`close_all`) ends synchronized movement as SyncMoveUndo does: the
    /// task leaves the shared list of tasks in sync, which is in the state lent to it.
    #[test]
    fn closing_a_task_takes_it_out_of_synchronized_movement() {
        use rapid_vm::ext::{Extensions, TaskState};
        let mut lent = Extensions::default();
        lent.get_or_default::<SharedTasking>().in_sync = vec!["T_ROB1".into(), "T_ROB2".into()];
        let members = vec!["T_ROB1".to_string(), "T_ROB2".to_string()];
        let mode = SyncMode { task: "T_ROB2".into(), point: "sync1".into(), members, suspended: false };
        let mut own = TaskingState { sync_move: Some(mode), move_round: Some(3), ..TaskingState::default() };
        own.close_all_lent(&mut lent);
        assert_eq!(own.sync_move, None);
        assert_eq!(own.move_round, None);
        assert_eq!(lent.get::<SharedTasking>().map(|s| s.in_sync.clone()), Some(vec!["T_ROB1".to_string()]));
    }

    #[test]
    fn robots_are_numbered_by_order_unless_the_configuration_numbers_them() {
        // T_ROB2, a positioner's task T_STN1, T_ROB1: by order ROB_1 and ROB_2.
        let tasks = vec![task("T_ROB2", true), task("T_STN1", false), task("T_ROB1", true)];
        let mut shared = SharedTasking::new(tasks);
        assert_eq!([0, 1, 2].map(|t| shared.robot_number(t)), [Some(1), None, Some(2)]);
        // The groups name ROB_2 for T_ROB2 and ROB_1 for T_ROB1: listed by number.
        shared.number_robots(vec![Some(2), None, Some(1)]).expect("numbered");
        assert_eq!([0, 1, 2].map(|t| shared.robot_number(t)), [Some(2), None, Some(1)]);
        assert_eq!(shared.robots(), [(1, 2), (2, 0)]);
        // One robot for two tasks, or a number for the positioner's task, is refused.
        assert!(shared.number_robots(vec![Some(1), None, Some(1)]).is_err());
        assert!(shared.number_robots(vec![Some(2), Some(3), Some(1)]).is_err());
        assert_eq!(shared.robots(), [(1, 2), (2, 0)]);
    }
}
