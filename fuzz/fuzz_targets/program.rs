//! Fuzz target `program`: the bytes drive a structure-aware generator
//! (`rapid_fuzz::program`) that writes whole, mostly well-typed RAPID programs of
//! several modules; each is checked, compiled and run for a bounded number of steps.
//!
//! Invariants: nothing panics; a program the checker accepts is compiled (a compile
//! error other than "not supported by `rapid run` yet" means check and run disagree,
//! issue 23 item 2).
#![no_main]

use arbitrary::Unstructured;
use libfuzzer_sys::fuzz_target;
use rapid_controller::builtin_set::load;
use rapid_sema::SourceInput;
use rapid_vm::{Exit, LoadError, RecordingHost};

fuzz_target!(|data: &[u8]| {
    // A crash that kills the process before libFuzzer can save the input (a stack
    // overflow) is found by naming a file to hold each input as it starts.
    if let Some(path) = std::env::var_os("RAPID_FUZZ_LAST_INPUT") {
        let _ = std::fs::write(path, data);
    }
    let mut u = Unstructured::new(data);
    let Ok(program) = rapid_fuzz::program::generate(&mut u) else { return };
    let files: Vec<SourceInput> = program
        .modules
        .iter()
        .enumerate()
        .map(|(idx, text)| SourceInput::from_bytes(format!("m{idx}.mod"), text.clone().into_bytes()))
        .collect();
    let mut loaded = match load(&files, "main") {
        Ok(loaded) => loaded,
        Err(LoadError::Unsupported(errors)) => {
            for error in errors {
                assert!(error.message.contains("not supported"), "check accepted, run refused: {}", error.message);
            }
            return;
        }
        Err(_) => return,
    };
    rapid_controller::bindings::sockets::of_mut(loaded.vm.resources_mut()).set_offline(true);
    let mut host = RecordingHost::default();
    for _ in 0..20 {
        match loaded.vm.run(&mut host, 1_000) {
            Exit::Budget => {}
            Exit::Wait(seconds) => loaded.vm.time += seconds,
            _ => break,
        }
    }
});
