//! Fuzz target `manifest`: arbitrary bytes as a `rapid.toml` project manifest through
//! its reader (`rapid_controller::assembly::inputs::manifest::read`), as if the file
//! stood in the repository's `examples/pick_and_place_cell` folder, so paths the seeds
//! name (`../pick_and_place.mod`, `eio.cfg`) are found. Nothing may panic; every
//! finding's span lies in the text, on character boundaries, in the text's order;
//! reading twice gives the same findings; each task has its list of modules.
#![no_main]

use std::path::PathBuf;

use libfuzzer_sys::fuzz_target;
use rapid_controller::assembly::inputs::manifest;

fn manifest_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples/pick_and_place_cell/rapid.toml")
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    // A `**` pattern walks up to 10,000 folders of the disk per input (an absolute or
    // `../..` one, the whole machine's): correct, but it would make the fuzzer a disk
    // scanner. The glob matcher has unit tests of its own.
    if text.contains("**") {
        return;
    }
    let path = manifest_path();
    let read = manifest::read(&path, text);
    let mut last = 0;
    for finding in &read.findings {
        let span = &finding.span;
        assert!(span.start <= span.end && span.end <= text.len(), "span {span:?} of `{}`", finding.message);
        assert!(text.is_char_boundary(span.start) && text.is_char_boundary(span.end), "span {span:?} splits a char");
        assert!(span.start >= last, "findings out of order at {span:?}");
        assert!(!finding.message.is_empty(), "a finding without a message at {span:?}");
        last = span.start;
    }
    // `check` and `run` find a task's modules by the task's index.
    assert_eq!(read.modules.len(), read.sys.tasks.len(), "one module list per task");
    let again = manifest::read(&path, text);
    assert_eq!(again.findings, read.findings, "reading twice gave different findings");
});
