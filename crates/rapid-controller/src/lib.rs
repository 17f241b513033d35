//! rapid-controller: the task system of the virtual controller (§1.20). Several
//! program tasks, each its own `rapid_vm::Vm`, run pseudo-parallel: round-robin one
//! statement each among the busy tasks of the top level, a background task only
//! while the tasks it stands behind are idle. What tasks share lives here and is
//! handed to the task that runs: the I/O system and sync points
//! (`rapid_vm::builtins::Shared`) and the global persistents ([`pers::PersStore`]).
//!
//! No IO of its own: output and operator input go through the `Host` the caller gives.

mod alone;
pub mod boot;
pub mod ops;
pub mod pers;
pub mod run;
pub mod schedule;
pub mod task;
mod types;

pub use ops::{ProgramState, StartMode, StopKind};
pub use run::{Bound, ClockPolicy, RunBounds, WallClock};
pub use schedule::{Controller, SystemExit};
pub use task::{TaskEnd, TaskKind, TaskSpec, TrustLevel};
