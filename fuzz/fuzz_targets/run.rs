//! Fuzz target `run`: arbitrary bytes as a module; when it checks clean, it is
//! compiled and run for a bounded number of steps (waits advance the virtual clock).
//! Nothing may panic: bad programs end with a RAPID error or the bound.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rapid_controller::builtin_set::load;
use rapid_sema::SourceInput;
use rapid_vm::{Exit, RecordingHost};

fuzz_target!(|data: &[u8]| {
    let files = vec![SourceInput::from_bytes("a.mod", data.to_vec())];
    let Ok(mut loaded) = load(&files, "main") else { return };
    // No network and no file root: a fuzzed program must not wait on real sockets
    // or write files (file built-ins raise their errors without a root).
    rapid_controller::bindings::sockets::of_mut(loaded.vm.resources_mut()).set_offline(true);
    let mut host = RecordingHost::default();
    // 20,000 steps: enough to reach deep into a program, bounded even when each step
    // copies a large array.
    for _ in 0..20 {
        match loaded.vm.run(&mut host, 1_000) {
            Exit::Budget => {}
            Exit::Wait(seconds) => loaded.vm.time += seconds,
            _ => break,
        }
    }
});
