//! The executor's questions to the embedder's extensions (`crate::embed::TaskHooks`):
//! the core loop asks these, never an extension's state.

use super::Vm;

impl Vm {
    /// The time until which the program owes an extension a wait (a move's wait a
    /// trap cut short): the earliest any extension names.
    #[inline]
    pub(super) fn program_hold(&self) -> Option<f64> {
        let mut hold: Option<f64> = None;
        for hooks in self.builtins.hooks() {
            if let Some(until) = hooks.program_hold(&self.resources) {
                hold = Some(hold.map_or(until, |h| h.min(until)));
            }
        }
        hold
    }

    /// A built-in call returned: each extension logs what it noticed and publishes
    /// what other tasks read; `held_after_call` says whether the program now owes one
    /// a wait (the fast loop then hands over to the one-at-a-time loop).
    #[inline]
    pub(super) fn after_builtin_hooks(&mut self) {
        let mut held = false;
        let mut events = Vec::new();
        // The hooks are `&'static`: copied out, they leave `self` free to log.
        for at in 0..self.builtins.hooks().len() {
            let hooks = self.builtins.hooks()[at];
            held |= hooks.after_builtin(&mut self.resources, self.time, &mut events);
            if !events.is_empty() {
                self.log_pending(std::mem::take(&mut events));
            }
        }
        self.held_after_call = held;
    }

    /// Whether an extension stands held by the program (a robot StopMove stopped).
    pub(super) fn extension_held(&self) -> bool {
        self.builtins.hooks().iter().any(|hooks| hooks.held(&self.resources))
    }

    /// The program is loaded: each extension learns the predefined data it works with.
    pub(crate) fn extensions_loaded(&mut self, program: &rapid_sema::Program) {
        for hooks in self.builtins.hooks() {
            hooks.loaded(&mut self.resources, program);
        }
    }

    /// The next change an extension knows of by itself (a scheduled signal change).
    pub(super) fn next_extension_event(&mut self) -> Option<f64> {
        let mut next: Option<f64> = None;
        for hooks in self.builtins.hooks() {
            if let Some(at) = hooks.next_event(&mut self.resources) {
                next = Some(next.map_or(at, |n| n.min(at)));
            }
        }
        next
    }

    /// The value of signal data read in an expression, from the extension that keeps
    /// the signals (see `TaskHooks::read_signal`); `Err(None)` when none does.
    pub(super) fn read_signal(&mut self, data: &crate::value::Value) -> Result<f64, Option<String>> {
        for hooks in self.builtins.hooks() {
            if let Some(read) = hooks.read_signal(&mut self.resources, self.time, data) {
                return read;
            }
        }
        Err(None)
    }

    /// The program's data was initialised again (PP to Main): the extensions connect
    /// what they connect from the start (the configuration's signals).
    pub(super) fn extensions_data_initialised(&mut self) {
        for hooks in self.builtins.hooks() {
            hooks.data_initialised(&mut self.resources, &mut self.storage);
        }
    }

    /// The set of built-ins the task runs with.
    pub fn builtins(&self) -> &std::sync::Arc<crate::builtins::Builtins> {
        &self.builtins
    }
}
