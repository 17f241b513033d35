//! How a task is given its outside world (`crate::world`): the file system its devices
//! live on, its network and its clocks.

use super::Vm;

impl Vm {
    /// Gives the task its outside world (the calendar starts from the world clock's
    /// time now). Without one the task has none (see [`crate::world`]).
    pub fn set_world(&mut self, world: crate::world::World) {
        let crate::world::World { files, net, clock } = world;
        self.wall_epoch = clock.wall_seconds();
        self.resources.devices.set_file_system(files);
        let mut net = Some(net);
        let builtins = self.builtins.clone();
        for hooks in builtins.hooks() {
            hooks.world_given(&mut self.resources, &mut net, &clock);
        }
        self.world_given = true;
    }

    /// Whether [`Vm::set_world`] gave the task a world.
    pub fn has_world(&self) -> bool {
        self.world_given
    }
}
