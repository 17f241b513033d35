//! rapid-sema: name resolution, type checking and the diagnostics of `rapid check`.

pub mod codes;
