//! The built-ins every task of the controller runs with: the language's own
//! (`rapid_vm`'s core families) and those of the extensions the controller installs —
//! multitasking (`rapid_tasks`), I/O signals (`rapid_signals`), the robot
//! (`rapid_robot`) and the controller's bindings (files, sockets,
//! configuration data, RMQ). Every front end loads its tasks through the assembly
//! (`crate::assembly::system`), and every test or tool that loads a program of its own
//! loads through [`load_with`]: one place decides what a task can call, so a program
//! that moves a robot or opens a file loads wherever it runs.

use std::sync::{Arc, LazyLock};

use rapid_sema::{Options, SourceInput};
use rapid_vm::builtins::Builtins;
use rapid_vm::embed::Extension;
use rapid_vm::{LoadError, Loaded};

/// The extensions the controller installs, one a line, in registration order.
static EXTENSIONS: &[&Extension] = &[
    &rapid_tasks::EXTENSION,              // multitasking (the robot reads the task list)
    &rapid_signals::EXTENSION,            // I/O signals (the robot reads and sets them)
    &rapid_robot::EXTENSION,              // the robot
    &crate::bindings::files::EXTENSION,   // files and folders
    &crate::bindings::sockets::EXTENSION, // sockets
    &crate::bindings::cfgdata::EXTENSION, // configuration data
    &crate::bindings::rmq::EXTENSION,     // RAPID Message Queue
];

static STANDARD: LazyLock<Arc<Builtins>> = LazyLock::new(|| Arc::new(Builtins::new(EXTENSIONS)));

/// The controller's set of built-ins: the core and every extension (built once,
/// shared by every task).
pub fn standard() -> Arc<Builtins> {
    STANDARD.clone()
}

/// Checks, compiles and initialises the task made of `files` with the controller's
/// set of built-ins ([`standard`]), ready to run `entry` (`rapid_vm::load_in`).
pub fn load_with(files: &[SourceInput], entry: &str, options: &Options) -> Result<Loaded, LoadError> {
    rapid_vm::load_in(files, entry, options, standard())
}

/// [`load_with`] with default checking options.
pub fn load(files: &[SourceInput], entry: &str) -> Result<Loaded, LoadError> {
    load_with(files, entry, &Options::default())
}

#[cfg(test)]
mod tests {
    use super::standard;

    /// One built-in of each binding: in the standard set, not in the language's core.
    const BINDINGS: &[&str] = &[
        "Open",
        "ReadStr",
        "ModExist",
        "SocketCreate",
        "SocketReceive",
        "ReadCfgData",
        "GetModalPayLoadMode",
        "RMQSendMessage",
        "IRMQMessage",
        "SetDO",
        "WaitDI",
        "ISignalDI",
        "IOEnable",
        "WaitSyncTask",
        "TestAndSet",
        "WaitTestAndSet",
        "GetTaskName",
        "TaskRunMec",
        "TaskRunRob",
        "TaskIsActive",
        "TaskIsExecuting",
        "GetTSPStatus",
        "MotionPlannerNo",
        "GetMecUnitName",
        "GetServiceInfo",
    ];

    #[test]
    fn the_standard_set_runs_the_controllers_bindings() {
        let set = standard();
        let core = rapid_vm::builtins::Builtins::core();
        for name in BINDINGS {
            assert!(set.lookup(name).is_some(), "{name} is not in the standard set");
            assert!(core.lookup(name).is_none(), "{name} is a binding of the controller's, not the core's");
        }
    }

    /// The catalogue, the set's families and `not_yet.rs` agree: every catalogue
    /// routine runs once or is refused with a reason, here where the full set is.
    #[test]
    fn the_controllers_set_is_in_step_with_the_catalogue() {
        let wrong = rapid_vm::builtins::out_of_step(&standard());
        assert!(wrong.is_empty(), "built-ins out of step:\n{}", wrong.join("\n"));
    }

    #[test]
    fn the_controllers_tasks_run_the_robot() {
        assert!(standard().lookup("MoveL").is_some());
        assert!(standard().lookup("SyncMoveOn").is_some());
    }
}
