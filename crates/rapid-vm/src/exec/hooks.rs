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

    /// The set of built-ins the task runs with.
    pub fn builtins(&self) -> &std::sync::Arc<crate::builtins::Builtins> {
        &self.builtins
    }
}
