//! What a built-in family defined outside this crate uses of the interpreter: an
//! embedder's [`crate::embed::Extension`] registers families written like the
//! language's own, and this module is the one place they take the interpreter's
//! helpers from (issue 19: the controller's bindings moved out of the VM).
//!
//! Kept small on purpose: a family reads its arguments through [`Ctx`], finds them by
//! parameter name ([`layout!`](crate::layout)), raises RAPID errors
//! (`Ctx::error`, with `crate::errnames::Err`), waits as
//! the language's waiting instructions do, and keeps its own state in the task's
//! extension slot (`Resources::extensions`). Anything else a family needs is added
//! here deliberately, not reached through a private path.
//!
//! What this module must not know: any extension.

pub use crate::builtins::interrupts::{interrupt_number, next_due, Source as InterruptSource};
pub use crate::builtins::io_visualize::{step as visualize_step, BoxArgs};
pub use crate::builtins::pendant::value_text;
pub use crate::builtins::signature::{of as signature, Signature};
pub use crate::builtins::wait::{next_event, wait_again, wait_over, wait_started};
pub use crate::builtins::{native, present, read_literal, Ctx, Family, Resources, StopKind};
pub use crate::layout;
pub use crate::world::devices;

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

// used by the tasks crate (rapid-tasks): which task this is and the task names are
// the core's (`builtins::tasks`), as are the requests to the controller.
pub use crate::builtins::stands_still;
pub use crate::builtins::tasks::{
    ask, named_task as task_named, other_task, ExtensionReply, Reply, Request, SharedTasks, TaskPlace,
};
pub use crate::errnames::Err;
pub use crate::error::RapidError;
pub use crate::value::Value;

// used by the controller's RMQ binding: a message's data travels by its type's name
// and is written as a RAPID literal for a client.
pub use crate::builtins::typenames::TypeNames;
pub use crate::format::{aggregate_to_text, bool_to_text, dnum_to_text, num_to_text, string_to_literal};
pub use crate::value::{Array, Record};

// used by the robot's tasking users (rapid-robot's foreign, moves, pause, readback,
// stepbwd, store, syncmove, sysdata and units take the interpreter from here only).
pub use crate::value::{Opaque, OpaqueState, Place, Root};
