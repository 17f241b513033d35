//! Catalogue chapter: motion.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[];
