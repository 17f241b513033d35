//! What a controller reaches into a task for: the globals it shares with other tasks
//! (persistents), the hand-over of the state all tasks share, and event routines.

use super::Vm;
use crate::value::Value;

impl Vm {
    /// The value of global `idx`.
    pub fn global(&self, idx: u32) -> Option<&Value> {
        self.storage.globals.get(idx)
    }

    /// The module-level data of a name (GetDataVal from another task): its global and
    /// whether it is a constant.
    pub fn global_by_name(&self, name: &str) -> Option<(u32, bool)> {
        self.data_by_name.get(&name.to_lowercase()).map(|d| (d.global, d.constant))
    }

    /// Gives global `idx` a value (SetDataVal from another task): recorded as written.
    pub fn set_global(&mut self, idx: u32, value: Value) {
        if let Some(slot) = self.storage.globals.get_mut(idx) {
            *slot = value;
        }
    }

    /// Gives global `idx` the value another task gave a persistent they share: not
    /// recorded as written, being no change of this task's.
    pub fn sync_global(&mut self, idx: u32, value: Value) {
        self.storage.globals.sync(idx, value);
    }

    /// The globals written since [`Vm::clear_global_writes`] (a controller finds there
    /// what a task changed of the persistents it shares).
    pub fn global_writes(&self) -> crate::exec::storage::GlobalWrites<'_> {
        self.storage.globals.writes()
    }

    /// Forgets the globals written so far.
    pub fn clear_global_writes(&mut self) {
        self.storage.globals.clear_writes();
    }

    /// Swaps the controller's shared state (I/O system, sync points) with the task's:
    /// before the task runs, and back after.
    pub fn exchange_shared(&mut self, shared: &mut crate::builtins::Shared) {
        self.resources.exchange_shared(shared);
        for hooks in self.builtins.hooks() {
            hooks.exchange_shared(&mut self.resources, &mut shared.extensions);
        }
    }

    /// Logs a state change of the task (operational domain, information), as the
    /// controller does when a program starts or stops.
    pub fn log_state(&mut self, (number, title): (u32, &str), line: String) {
        self.events.push(crate::events::Event {
            seq: 0,
            domain: crate::events::OPERATIONAL_DOMAIN,
            number,
            kind: crate::events::EventKind::Info,
            time: self.time,
            title: title.to_string(),
            details: Vec::new(),
            lines: vec![line],
            place: None,
        });
    }

    /// Whether an interrupt waits for its trap or a trap is running.
    pub fn has_interrupt_work(&self) -> bool {
        !self.resources.interrupts.queue.is_empty() || self.frames.iter().any(|f| f.interrupted)
    }

    /// Whether the task has a procedure `name` (an event routine the configuration names).
    pub fn has_procedure(&self, name: &str) -> bool {
        self.procs_by_name.contains_key(&name.to_lowercase())
    }

    /// Runs the procedure `name` (an event routine of system event `event`, 1 for
    /// POWER_ON … 7 for STEP) to its end, moving the task's clock over its waits; the
    /// task then starts `entry` afresh. Err with the error no handler took; Ok(false)
    /// when the task has no such procedure.
    pub fn run_event_routine(
        &mut self,
        host: &mut dyn crate::host::Host,
        name: &str,
        event: u8,
        entry: u32,
    ) -> Result<bool, super::Unhandled> {
        let Some(&idx) = self.procs_by_name.get(&name.to_lowercase()) else { return Ok(false) };
        if !self.start_routine(idx) {
            return Ok(false);
        }
        self.resources.tasks.event = event;
        let outcome = loop {
            match self.run(host, u64::MAX) {
                super::Exit::Wait(seconds) => self.time += seconds,
                super::Exit::Budget => {}
                super::Exit::Unhandled(unhandled) => break Err(unhandled),
                super::Exit::Done | super::Exit::Stopped | super::Exit::CycleEnded => break Ok(true),
            }
        };
        self.resources.tasks.event = 0;
        self.start_routine(entry);
        outcome
    }
}
