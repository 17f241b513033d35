//! rapid-vm: executes RAPID programs checked by rapid-sema.
//!
//! Invariant: no IO of its own. Output, input, clocks and files reach it through host
//! traits; RAPID call depth lives in explicit frames, never on the Rust stack.

pub mod format;
