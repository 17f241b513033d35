//! What a built-in family defined outside this crate uses of the interpreter: an
//! embedder's [`crate::embed::Extension`] registers families written like the
//! language's own, and this module is the one door they take the interpreter's
//! items through (issue 19): rapid-robot, rapid-signals and the controller's bindings
//! name no other `rapid_vm::` path (`xtask/tests/ext_door.rs` holds them to it, with
//! an allow-list of the files still to move that may only shrink).
//!
//! Kept small on purpose: a family reads its arguments through [`Ctx`], finds them by
//! parameter name ([`layout!`](crate::layout)), raises RAPID errors
//! (`Ctx::error`, with [`Err`]), waits as the language's waiting instructions do,
//! keeps its own state in the task's extension slot (`Resources::extensions`) and
//! reaches the outside world through the host's traits. The items are re-exported
//! one by one, in groups (a whole module only for the file devices); where a family
//! would reach into the interpreter's state, a narrow question is asked here instead
//! ([`call_site`], [`task_index`], [`type_named`]). Anything else a family needs is
//! added here deliberately, not reached through a private path.
//!
//! What this module must not know: any extension.

// The built-in's call: its context, arguments by parameter name, how it stops.
pub use crate::builtins::signature::{of as signature, Signature, ABSENT};
pub use crate::builtins::{native, present, read_literal, Ctx, Family, Resources, StopKind};
pub use crate::layout;

// Errors: a family raises the language's errors by name.
pub use crate::errnames::Err;
pub use crate::error::RapidError;

// Values: what the arguments and results are, and the places a family reads and
// writes (a data reference, an opaque handle's slot).
pub use crate::value::{Array, Opaque, OpaqueState, Place, Record, Root, Value, MAX_STRING_CHARS};

// The extension itself: its families and hooks, the state it keeps per task and
// shares between tasks, and the event-log entries its hooks hand back. `Shared` is
// the controller's shared state: an extension keeps its shared part in
// `Shared::extensions` (swapped by its hook) or `Shared::lent` (lent to the running
// task whole) and may give the embedder a typed view of it.
pub use crate::builtins::Shared;
pub use crate::embed::{Extension, Extensions, PendingEvent, TaskHooks, TaskState};
pub use crate::events::{Event, EventKind, MOTION_DOMAIN};

// The task's data store. Re-exported, not narrowed: `TaskHooks` hands it to a family
// (`poll`, `program_stopped`, `data_initialised`), which reads and writes it by place
// (`get`, `set`) and, to connect configured data, by global (`globals`).
pub use crate::exec::storage::Storage;

// Waiting, interrupts and the language's own I/O helpers a family joins in.
pub use crate::builtins::interrupts::{
    interrupt_number, next_due, AnalogTrigger, SampleTrigger, Source as InterruptSource,
};
pub use crate::builtins::io_visualize::{step as visualize_step, BoxArgs};
pub use crate::builtins::pendant::value_text;
pub use crate::builtins::wait::{next_event, wait_again, wait_over, wait_started};

// The outside world a family reaches through the host's traits: the file devices,
// files and folders, the network and the clock its waits run on (`SilentNetwork`:
// the network where no peer ever sends, which a family's own tests run on).
pub use crate::world::devices;
pub use crate::world::memory::SilentNetwork;
pub use crate::world::{Clock, StoppedClock};
pub use crate::world::{FileKind, FileMeta, FileSystem, HostFile, OpenMode};
pub use crate::world::{Network, NoNetwork, TcpConn, TcpListen, UdpConn};

/// Where the running call is: its call depth and the instruction in its routine. A
/// waiting built-in that runs again (`StopKind::Repeat`) keys its wait by this, so a
/// wait begun by another call is never taken for its own.
pub fn call_site(ctx: &Ctx<'_>) -> (usize, u32) {
    (ctx.chain.len(), ctx.chain.last().map_or(0, |frame| frame.position().1))
}

/// The index of the task in the task system (its place in the configuration, from 0).
pub fn task_index(ctx: &Ctx<'_>) -> usize {
    ctx.resources.tasks.index()
}

/// The program's type named `name` (any letter case), by its number in this task:
/// what a family building a record of a declared type (`pos`, `robtarget`) gives it.
pub fn type_named(ctx: &Ctx<'_>, name: &str) -> Option<rapid_sema::types::TypeId> {
    ctx.resources.type_names.by_name.get(&name.to_ascii_lowercase()).copied()
}

// used by the tasks crate (rapid-tasks) and the robot's tasking users: which task this
// is and the task names are the core's (`builtins::tasks`), as are the requests to
// the controller (another task's data or robot).
pub use crate::builtins::stands_still;
pub use crate::builtins::tasks::{
    ask, named_task as task_named, other_task, ExtensionReply, Reply, Request, SharedTasks, TaskPlace,
};

// used by the controller's RMQ binding: a message's data travels by its type's name
// and is written as a RAPID literal for a client.
pub use crate::builtins::typenames::TypeNames;
pub use crate::format::{aggregate_to_text, bool_to_text, dnum_to_text, num_to_text, string_to_literal};
