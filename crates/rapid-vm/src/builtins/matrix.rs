//! Matrix functions and FitCircle (§1.15). Not implemented yet.

use super::Entries;

pub(super) static ENTRIES: Entries = &[];
