//! System information and program-state functions (§1.17). Not implemented yet.

use super::Entries;

pub(super) static ENTRIES: Entries = &[];
