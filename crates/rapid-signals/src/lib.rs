//! rapid-signals: RAPID's I/O signals (§1.9), an extension of the interpreter core
//! (`rapid_vm::ext::Extension`, [`EXTENSION`]) on the task's I/O system
//! (`rapid_io::IoSystem`). It holds the task's I/O state ([`IoState`], in the task's
//! extension slot, reached through [`IoAccess`]) and the part every task of a
//! controller shares ([`SharedIo`], in `rapid_vm::ext::Shared::extensions`), the
//! signal built-ins (`io.rs`: AliasIO, Set, SetDO, TestDI, …), the waits on signals
//! (`waits.rs`: WaitDI … WaitAO), the I/O devices and networks (`units.rs`), the
//! signal interrupts (`interrupts.rs`: ISignalDI … ISignalAO), and what the
//! interpreter's loop asks of signals through `rapid_vm::ext::TaskHooks` (signal
//! data read in expressions, the changes signal interrupts look at, the next
//! scheduled change).
//!
//! It sits above rapid-vm and below the robot (rapid-robot sets trigger outputs and
//! reads conveyors' inputs here) and the controller (which builds the I/O system from
//! EIO.cfg and hands it in, [`SignalsVm::install_io`]).
//!
//! What it must not know: the robot, the controller's configuration files, any
//! front end. The interpreter keeps the language: signal data as values (handles),
//! interrupts and waits as mechanisms.

mod interrupts;
pub mod io;
mod units;
mod vm;
mod waits;

pub use io::{
    io_error, kind_name, order, read_signal, signal, IoAccess, IoHooks, IoState, Reaction, SharedIo, SharedIoAccess,
    HOOKS,
};
pub use vm::SignalsVm;

use rapid_vm::ext::Extension;

/// The I/O signals as an extension of the interpreter: registered before the robot's
/// (which reads and sets signals).
pub static EXTENSION: Extension = Extension {
    name: "I/O signals",
    families: &[&io::FAMILY, &interrupts::FAMILY, &waits::FAMILY, &units::FAMILY],
    hooks: Some(&HOOKS),
    init: None,
};
