//! Catalogue chapter: interrupts.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[];
