//! The built-ins every task of the controller runs with: the standard set
//! ([`crate::builtin_set`]: the language's own and the extensions the controller
//! installs). Every front end loads its tasks through the assembly
//! (`crate::assembly::system`), which loads with this set: one place decides what a
//! task can call.

use std::sync::Arc;

use rapid_vm::builtins::Builtins;

/// The controller's set of built-ins (built once, shared by every task).
pub fn builtins() -> Arc<Builtins> {
    crate::builtin_set::standard()
}

#[cfg(test)]
mod tests {
    use super::builtins;

    /// The catalogue, the set's families and `not_yet.rs` agree: every catalogue
    /// routine runs once or is refused with a reason, here where the full set is.
    #[test]
    fn the_controllers_set_is_in_step_with_the_catalogue() {
        let wrong = rapid_vm::builtins::out_of_step(&builtins());
        assert!(wrong.is_empty(), "built-ins out of step:\n{}", wrong.join("\n"));
    }

    #[test]
    fn the_controllers_tasks_run_the_robot() {
        assert!(builtins().lookup("MoveL").is_some());
        assert!(builtins().lookup("SyncMoveOn").is_some());
    }
}
