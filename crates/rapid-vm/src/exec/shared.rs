//! What a controller of several tasks reaches into a task for: the globals it shares
//! with other tasks (persistents) and the hand-over of the state all tasks share.

use super::Vm;
use crate::value::Value;

impl Vm {
    /// The value of global `idx`.
    pub fn global(&self, idx: u32) -> Option<&Value> {
        self.storage.globals.get(idx as usize)
    }

    /// Gives global `idx` a value (the controller, sharing persistents between tasks).
    pub fn set_global(&mut self, idx: u32, value: Value) {
        if let Some(slot) = self.storage.globals.get_mut(idx as usize) {
            *slot = value;
        }
    }

    /// Swaps the controller's shared state (I/O system, sync points) with the task's:
    /// before the task runs, and back after.
    pub fn exchange_shared(&mut self, shared: &mut crate::builtins::Shared) {
        self.resources.exchange_shared(shared);
    }
}
