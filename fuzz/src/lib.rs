//! Helpers of the fuzz targets: the structure-aware RAPID program generator
//! (`program`, shared by the `program`, `controller` and `lsp` targets), the `rws`
//! target's system, requests and answer checks, and the `lsp` target's sessions.

pub mod lsp;
pub mod program;
pub mod rws;
