//! Sockets (§1.10). Not implemented yet: every entry here is refused at load.

use super::Entries;

/// Open sockets of the task.
#[derive(Default)]
pub struct SocketState {}

impl SocketState {
    /// Closes every socket.
    pub fn close_all(&mut self) {}
}

pub(super) static ENTRIES: Entries = &[];
