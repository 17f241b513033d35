//! rapid-lib: the one catalogue of RAPID's predefined types, data, instructions and
//! functions. The checker, the VM, the formatter and the language server all read it.
//!
//! Invariant: declarations only. This crate parses its own entries with rapid-syntax
//! and hands out the trees; it does no checking and no IO.

pub mod catalogue;
mod load;

pub use load::{load, BuiltinItem, LoadedCatalogue, LoadedEntry};
