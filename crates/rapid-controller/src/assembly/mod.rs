//! Assembly: what turns the PATHs a front end is given (a module, a folder of modules,
//! a `.pgf`, a controller backup, a `rapid.toml` manifest) and its options into a
//! booted [`Controller`](crate::Controller) ready to run. This is the one place of the
//! crate that reads files: the inputs ([`inputs`]), the stimulus ([`stimulus`]) and the
//! system they make ([`system`]). `rapid run`, `rapid serve` and `rapid dap` all come
//! through [`system::assemble`] ([`assemble`]); `rapid check` and `rapid lsp` read the
//! same [`inputs`].
//!
//! What it must not know: the command line (options arrive as plain structs), the
//! terminal (notes and findings are handed back as data for the front end to print),
//! exit statuses and output formats.

pub mod inputs;
pub mod stimulus;
pub mod system;
#[cfg(test)]
mod tests;

pub use system::{assemble, Assembled, Assembly, AssemblyError, LoadOptions};
