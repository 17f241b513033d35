//! Files and folders on the controller's devices (§1.16) and character/binary I/O
//! on them (§1.10). Not implemented yet: every entry here is refused at load.

use super::Entries;

/// Open files and directories of the task.
#[derive(Default)]
pub struct FileState {}

impl FileState {
    /// Closes every open file and directory.
    pub fn close_all(&mut self) {}
}

pub(super) static ENTRIES: Entries = &[];
