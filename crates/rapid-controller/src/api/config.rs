//! The system parameters for front ends (RWS's `/rw/cfg`): the configuration domains
//! the controller booted with (a backup's or a layout's `EIO.cfg`, `SYS.cfg`,
//! `MOC.cfg`, …), as parsed files.

use super::Session;

impl Session {
    /// The configuration domains as (domain, parsed file) pairs, in the order the
    /// system gave them; empty when the program was booted without configuration.
    /// They are the first task's, which its WriteCfgData changes (each task reads and
    /// writes a copy of its own, as `rapid_vm::builtins::cfgdata` keeps them).
    pub fn configuration(&self) -> &[(String, rapid_config::CfgFile)] {
        self.controller.tasks.first().map_or(&[], |t| t.loaded.vm.resources().cfgdata.domains())
    }
}
