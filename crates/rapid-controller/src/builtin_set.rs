//! The standard set of built-ins: the language's own (rapid-vm's core families) and
//! the extensions of the controller's side, the one list of what a task of a system
//! can call. Every front end loads its tasks with it (the assembly, through
//! `boot::builtins`; tests and tools that load a program of their own, through
//! [`load_with`]), so a program that opens a file or a socket loads wherever it runs.

use std::sync::{Arc, LazyLock};

use rapid_sema::{Options, SourceInput};
use rapid_vm::builtins::Builtins;
use rapid_vm::embed::Extension;
use rapid_vm::{LoadError, Loaded};

/// The extensions every task runs with, one line each, in registration order.
static EXTENSIONS: &[&Extension] = &[
    &rapid_vm::builtins::motion::EXTENSION, // the robot
    &crate::bindings::files::EXTENSION,     // files and folders
    &crate::bindings::sockets::EXTENSION,   // sockets
    &crate::bindings::cfgdata::EXTENSION,   // configuration data
    &crate::bindings::rmq::EXTENSION,       // RAPID Message Queue
];

static STANDARD: LazyLock<Arc<Builtins>> = LazyLock::new(|| Arc::new(Builtins::new(EXTENSIONS)));

/// The standard set (built once, shared by every task).
pub fn standard() -> Arc<Builtins> {
    STANDARD.clone()
}

/// Checks, compiles and initialises the task made of `files` with the standard set,
/// ready to run `entry` (`rapid_vm::load_in`).
pub fn load_with(files: &[SourceInput], entry: &str, options: &Options) -> Result<Loaded, LoadError> {
    rapid_vm::load_in(files, entry, options, standard())
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
    ];

    #[test]
    fn the_standard_set_runs_the_controllers_bindings() {
        let set = standard();
        let core = rapid_vm::builtins::Builtins::core();
        for name in BINDINGS {
            assert!(set.lookup(name).is_some(), "{name} is not in the standard set");
            assert!(core.lookup(name).is_none(), "{name} is a binding of the controller's, not the core's");
        }
        assert!(set.lookup("MoveL").is_some(), "the robot's extension is in the set");
    }
}
