//! A task's side of the I/O system, for the controller that builds it: installing it
//! and connecting the configuration's signals (their program data) to it.

use rapid_vm::ext::Value;
use rapid_vm::Vm;

use crate::io::IoAccess;

/// What an embedder does with a task's signals ([`rapid_vm::Vm`]'s I/O).
pub trait SignalsVm {
    /// Installs the task's I/O system and connects the configuration's signals (their
    /// program data) to it.
    fn install_io(&mut self, system: rapid_io::IoSystem);

    /// Configured signals are connected from the start, also after PP to Main
    /// re-initialises the data. (A controller calls this with its shared I/O system
    /// handed in, for every task.)
    fn connect_configured_signals(&mut self);

    /// The configuration's signals the program names as data, with the kind of its
    /// data (`--virtual-io` adds those the I/O system lacks as virtual signals).
    fn configured_signals(&self) -> Vec<(String, rapid_io::SignalKind)>;

    /// The task's I/O system, if it has one (its signals, their change log).
    fn io_system(&self) -> Option<&rapid_io::IoSystem>;
}

impl SignalsVm for Vm {
    fn install_io(&mut self, system: rapid_io::IoSystem) {
        self.resources_mut().io_mut().system = Some(system);
        self.connect_configured_signals();
    }

    fn connect_configured_signals(&mut self) {
        for (global, value) in self.resources().io().configured_values() {
            self.set_global(global, value);
        }
    }

    fn configured_signals(&self) -> Vec<(String, rapid_io::SignalKind)> {
        let io = self.resources().io();
        io.configured
            .iter()
            .filter_map(|(global, name)| {
                let Value::Opaque(data) = self.global(*global)? else { return None };
                let kind = io.kinds.iter().find(|(ty, _)| *ty == data.ty)?.1;
                Some((name.clone(), kind))
            })
            .collect()
    }

    fn io_system(&self) -> Option<&rapid_io::IoSystem> {
        self.resources().io().system.as_ref()
    }
}
