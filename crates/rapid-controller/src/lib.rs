//! rapid-controller: the running system of the virtual controller, which every front
//! end uses.
//!
//! - [`boot`] assembles it: `boot::system::boot` takes the tasks' loaded programs and
//!   the configuration around them and builds the [`Controller`] at power on (tasks,
//!   the one I/O system, the robots, the program operations).
//! - [`Controller::run_until`] is the one run loop: to the end or a bound, the clock
//!   moved under a [`ClockPolicy`] with the front end's [`WallClock`]
//!   ([`Controller::move_clock`], which the API's turns share); a run nothing outside
//!   changes ends when it can no longer progress (`progress.rs`).
//! - A system of one task without system inputs or outputs runs alone (`alone.rs`):
//!   its VM in slices, as fast as the interpreter. Several tasks are the task system
//!   of §1.20 (`schedule`): round-robin one statement each among the busy tasks of the
//!   top level, a background task only while the tasks it stands behind are idle.
//!   What tasks share lives here and is handed to the task that runs: the I/O system
//!   and sync points (`rapid_vm::builtins::Shared`) and the global persistents
//!   ([`pers::PersStore`]).
//! - [`builtin_set`] is the set of built-ins every task runs with: the language's
//!   and the extensions the controller installs (the robot).
//! - [`ops`] holds the program operations (stop, start, motors, system signals).
//! - [`bindings`] holds the built-in families of the controller's side (files ...),
//!   each an extension of the interpreter (`rapid_vm::embed::Extension`);
//!   [`builtin_set`] is the set of built-ins every task of a system runs with.
//!
//! - [`host_std`] is the std world every task gets by default: the host's disk,
//!   network and clocks behind the VM's host traits (`rapid_vm::world`).
//! - [`assembly`] turns PATHs (a module, a folder, a `.pgf`, a backup, a manifest) and
//!   plain options into a booted system: the one assembly path of every front end, and
//!   the only part of the crate that reads files of its own (the inputs and the
//!   stimulus).
//!
//! What it must not know: no IO of its own outside [`assembly`] and [`host_std`] (no
//! sockets or terminal; a task's programs reach the host only through its world), no wall clock
//! (the front end's [`WallClock`]), no command-line options, output formats (trace,
//! report, logs) or exit statuses. Output and operator input go through the `Host`
//! the caller gives.

mod alone;
pub mod api;
pub mod assembly;
pub mod bindings;
pub mod boot;
pub mod builtin_set;
pub mod host_std;
pub mod ops;
pub mod pers;
mod power_on;
mod progress;
pub mod run;
pub mod schedule;
pub mod task;
#[cfg(test)]
mod test_support;
mod types;

pub use ops::{ProgramState, StartMode, StopKind};
pub use power_on::EventRoutineFailure;
pub use progress::StuckWait;
pub use run::{Bound, ClockPolicy, RunBounds, WallClock};
pub use schedule::{Controller, SystemExit};
pub use task::{TaskEnd, TaskKind, TaskSpec, TrustLevel};
