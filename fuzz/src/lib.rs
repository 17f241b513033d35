//! Helpers of the fuzz targets: the structure-aware RAPID program generator
//! (`program`), shared by the `program` target and its tests.

pub mod program;
