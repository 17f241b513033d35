//! Fuzz target `check`: arbitrary bytes through decoding, the lexer, the parser and the
//! checker (`rapid_sema::check` drives them all). Nothing may panic, checking the same
//! input twice must give the same diagnostics, and every span must lie inside its
//! file's text.
//!
//! Checking twice doubles the cost of an input, so determinism is tested on one input
//! in four (chosen by the input's bytes, so a finding reproduces): a nondeterministic
//! checker (a hash map's order leaking into the diagnostics) shows on many inputs.
//!
//! The input is split at its first 0xFF byte (when it has one) into two files, so the
//! cross-module paths of the checker (globals, duplicate modules) are exercised too.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rapid_sema::{check, Options, SourceInput};

fuzz_target!(|data: &[u8]| {
    let files = match data.iter().position(|&b| b == 0xFF) {
        Some(split) => vec![
            SourceInput::from_bytes("a.mod", data[..split].to_vec()),
            SourceInput::from_bytes("b.mod", data[split + 1..].to_vec()),
        ],
        None => vec![SourceInput::from_bytes("a.mod", data.to_vec())],
    };
    let twice = data.iter().fold(0u8, |a, b| a.wrapping_add(*b)) % 4 == 0;
    for syntax_only in [false, true] {
        let options = Options { syntax_only, ..Options::default() };
        let first = check(&files, &options);
        if twice {
            assert_eq!(first, check(&files, &options), "check is not deterministic");
        }
        for diag in &first {
            let text = &files[diag.file].text;
            assert!(diag.span.start <= diag.span.end, "inverted span {:?}", diag.span);
            assert!(diag.span.end as usize <= text.len(), "span {:?} past the end", diag.span);
        }
    }
});
