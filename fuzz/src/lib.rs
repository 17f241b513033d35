//! Helpers of the fuzz targets: the structure-aware RAPID program generator
//! (`program`, shared by the `program`, `controller` and `lsp` targets), the `rws`
//! target's system, requests and answer checks, the `lsp` target's sessions, and how
//! the `controller` target runs its tasks (`system`).

pub mod lsp;
pub mod program;
pub mod rws;
pub mod system;
