//! rapid-tasks: RAPID's multitasking (§1.20), an extension of the interpreter core
//! (`rapid_vm::ext::Extension`, [`EXTENSION`]). It holds what a task knows of the
//! other tasks of its system: their kinds and states ([`TaskInfo`]: motion task,
//! robot, NORMAL, executing), the robots' numbering, the sync points of WaitSyncTask
//! and of synchronized movement, each task's RAPID Message Queue configuration
//! ([`RmqConfig`]; the queues are the controller's RMQ binding's), and the built-ins
//! that read them (`tasking.rs`: WaitSyncTask, TestAndSet, WaitTestAndSet,
//! GetTaskName, TaskRunMec, TaskRunRob, TaskIsActive, TaskIsExecuting; `units.rs`:
//! GetTSPStatus, MotionPlannerNo, GetMecUnitName, GetServiceInfo). Its state is the
//! task's [`TaskingState`] (in the task's extension slot, reached through
//! [`TaskingAccess`]) and the part every task of a controller shares
//! ([`SharedTasking`], in `rapid_vm::ext::Shared::lent`, reached through
//! [`SharedTaskingAccess`]), which the core lends the running task whole
//! (`Resources::lent`): no hook runs around a statement for it.
//!
//! It sits above rapid-vm and below the robot (rapid-robot reads which task moves
//! which robot, meets the other tasks for synchronized movement and asks another
//! task's robot through the core's requests) and the controller (which builds the
//! task list from its configuration and serves the requests).
//!
//! What it must not know: the robot, I/O signals, the controller's configuration
//! files, any front end. The interpreter core keeps only what the language's own
//! built-ins need of tasks (`rapid_vm::ext::TaskPlace`: which task this is, the task
//! names, the requests to the controller, the controller-wide event log).

mod rmq;
mod tasking;
mod units;

pub use rmq::{RmqConfig, RmqKind};
pub use tasking::{
    meet, my_task, named_task, sync_point, task_list, MoveMeet, SharedTasking, SharedTaskingAccess, SyncMode, TaskInfo,
    Tasking, TaskingAccess, TaskingMut, TaskingState,
};
pub use units::planner_no;

use rapid_vm::ext::Extension;
use rapid_vm::ext::Resources;

/// Multitasking as an extension of the interpreter: registered before the robot's
/// (which reads the task list and meets the other tasks).
pub static EXTENSION: Extension =
    Extension { name: "tasks", families: &[&tasking::FAMILY, &units::FAMILY], hooks: None, init: Some(init) };

/// Puts the task's state in first: the built-ins find it sooner (a lookup scans the
/// slot in order).
fn init(resources: &mut Resources) {
    resources.extensions.insert(TaskingState::default());
}
