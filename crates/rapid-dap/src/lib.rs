//! `rapid dap`: a Debug Adapter Protocol server on the virtual controller's API
//! (`rapid_controller::api::Session`). A debugger front end (VS Code, nvim-dap, …)
//! launches a RAPID system, sets line and conditional breakpoints, sees the tasks
//! as threads with their call stacks, reads and writes data, evaluates RAPID
//! expressions, steps (into, over, out, and backward per §1.21), pauses and
//! continues; the pendant's lines come out as output events and its dialogs wait
//! for an answer given in the debug console. See `docs/dap.md`.
//!
//! The crate does no printing and knows no command line: the CLI hands it the input
//! and output streams and a [`Launcher`] that turns a launch request's arguments
//! into a booted session (as `rapid run` reads a module, folder, backup or manifest).
//!
//! Modules: `wire` (the base protocol's framing), `adapter` (requests, responses and
//! events; `adapter/inspect.rs` what a stopped program shows), `vars` (variable handles), `run` (the loop that reads requests while the
//! program runs).

mod adapter;
mod run;
mod vars;
mod wire;

use std::path::PathBuf;

pub use run::serve;

/// What a launch request asks for (its `arguments`, as the VS Code extension and
/// docs/dap.md name them).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LaunchArgs {
    /// `program`: the module files, folder, backup or manifest (one path or several).
    pub program: Vec<PathBuf>,
    /// `stimulus`: input changes at controller times, as `rapid run --stimulus`.
    pub stimulus: Option<PathBuf>,
    /// `tpInput`: the operator's answers to pendant dialogs, as `rapid run --tp-input`.
    pub tp_input: Option<PathBuf>,
    /// `stopOnEntry`: stand stopped at each task's entry routine after launch.
    pub stop_on_entry: bool,
}

/// A booted system the adapter debugs.
pub struct Launched {
    /// The session, standing stopped with its program pointers at the entry routines.
    pub session: rapid_controller::api::Session,
    /// Answers for the pendant's dialogs, given in order as they open.
    pub answers: Vec<String>,
}

/// Boots the system a launch request names (the CLI knows how paths become tasks).
pub trait Launcher {
    /// The booted system, or why it cannot be (shown to the user).
    fn launch(&self, args: &LaunchArgs) -> Result<Launched, String>;
}
