//! The VM's side of the I/O system: installing it and connecting the configuration's
//! signals (their program data) to it.

use super::Vm;
use crate::builtins::io::IoAccess;

impl Vm {
    /// Installs the task's I/O system and connects the configuration's signals (their
    /// program data) to it.
    pub fn install_io(&mut self, system: rapid_io::IoSystem) {
        self.resources.io_mut().system = Some(system);
        self.connect_configured_signals();
    }

    /// Configured signals are connected from the start, also after PP to Main
    /// re-initialises the data. (A controller calls this with its shared I/O system
    /// handed in, for every task.)
    pub fn connect_configured_signals(&mut self) {
        crate::builtins::io::connect_configured(&self.resources, &mut self.storage);
    }

    /// The configuration's signals the program names as data, with the kind of its
    /// data (`--virtual-io` adds those the I/O system lacks as virtual signals).
    pub fn configured_signals(&self) -> Vec<(String, rapid_io::SignalKind)> {
        let io = self.resources.io();
        io.configured
            .iter()
            .filter_map(|(global, name)| {
                let crate::value::Value::Opaque(data) = self.storage.globals.get(*global)? else { return None };
                let kind = io.kinds.iter().find(|(ty, _)| *ty == data.ty)?.1;
                Some((name.clone(), kind))
            })
            .collect()
    }

    /// The task's I/O system, if it has one (its signals, their change log).
    pub fn io_system(&self) -> Option<&rapid_io::IoSystem> {
        self.resources.io().system.as_ref()
    }
}
