//! Assembling a running system from what the front end collected (`system::boot`):
//! the tasks and their configuration, the I/O system (`io_config`), the robots of its motion tasks
//! and their external units and conveyors (`motion`, `robots`, `moc_units`), the
//! virtual signals of `--virtual-io` (`virtual_io`), from the configuration around the
//! tasks (`cell`); each task's file devices and configuration data (`task`, `cfgdata`).

pub mod cell;
pub mod cfgdata;
pub mod io_config;
pub mod moc_units;
pub mod motion;
pub mod robots;
pub mod system;
pub mod task;
pub mod virtual_io;
