//! Fuzz target `controller`: one to three tasks, each a program of the structure-aware
//! generator (`rapid_fuzz::program`), run together by the controller (round-robin,
//! shared persistents, one motion task) for at most 16,000 instructions (one task)
//! or 4,000 statements (several; `rapid_fuzz::system`), the clock moved on through
//! every wait. Nothing may panic.
#![no_main]

use arbitrary::Unstructured;
use libfuzzer_sys::fuzz_target;
use rapid_controller::builtin_set::load;
use rapid_controller::{Controller, TaskKind, TaskSpec, TrustLevel};
use rapid_sema::SourceInput;
use rapid_vm::RecordingHost;

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(n_tasks) = u.int_in_range(1..=3usize) else { return };
    let mut tasks = Vec::new();
    for idx in 0..n_tasks {
        let Ok(program) = rapid_fuzz::program::generate(&mut u) else { return };
        let files: Vec<SourceInput> = program
            .modules
            .iter()
            .enumerate()
            .map(|(m, text)| SourceInput::from_bytes(format!("t{idx}m{m}.mod"), text.clone().into_bytes()))
            .collect();
        let Ok(mut loaded) = load(&files, "main") else { return };
        rapid_controller::bindings::sockets::of_mut(loaded.vm.resources_mut()).set_offline(true);
        let kind = match u.int_in_range(0..=3u8).unwrap_or(0) {
            0 => TaskKind::Static,
            1 => TaskKind::SemiStatic,
            _ => TaskKind::Normal,
        };
        let spec = TaskSpec {
            name: if idx == 0 { "T_ROB1".to_owned() } else { format!("T_{idx}") },
            kind,
            trust: TrustLevel::SysFail,
            foreground: None,
            motion: idx == 0,
            robot: idx == 0,
            rmq: rapid_config::sys::Rmq::default(),
            shared_files: Vec::new(),
            robot_of: None,
        };
        tasks.push((spec, loaded));
    }
    // Two tasks declaring one PERS with different types is a load error: fine.
    let Ok(mut controller) = Controller::new(tasks, None) else { return };
    let mut host = RecordingHost::default();
    // 16 slices: a generated program's code is reached well within them, and longer
    // runs only go round its loops (the steps were most of an input's time at 40,000
    // instructions). Tasks together are charged statements: `rapid_fuzz::system`.
    rapid_fuzz::system::run(&mut controller, &mut host, n_tasks);
});
