//! The std world: the host's disk, network and clocks behind the VM's host traits
//! (`rapid_vm::world`). Every task the controller builds gets one unless its embedder
//! gave it another ([`install`], called by `Controller::new`), so every front end that
//! boots a system through the controller has the host's world by default.
//!
//! This module is the controller's only IO; the rest of the crate does none. The
//! device-name → folder mapping and the sandbox checks stay in the VM
//! (`rapid_vm::world::devices`), so they hold for every world; the folder the
//! devices live in (the controller root) is the front end's configuration
//! (`Devices::set_root`, set by `boot::task::configure`).

pub mod atomic;
mod clock;
mod files;
mod net;

use std::rc::Rc;

use rapid_vm::world::World;
use rapid_vm::Vm;

pub use clock::StdClock;
pub use files::StdFs;
pub use net::StdNetwork;

/// The host's world: its file system, its network, its clocks.
pub fn world() -> World {
    World { files: Box::new(StdFs), net: Box::new(StdNetwork), clock: Rc::new(StdClock::default()) }
}

/// Gives `vm` the host's world unless its embedder already gave it one.
pub fn install(vm: &mut Vm) {
    if !vm.has_world() {
        vm.set_world(world());
    }
}
