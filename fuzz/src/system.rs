//! How the `controller` target runs its tasks: in slices, the clock moved on through
//! every wait, for a bounded amount of work.
//!
//! A task run alone is charged its VM's instructions; tasks run together are charged
//! basic steps (statements), and one statement may run up to 10,000 instructions
//! before it gives way (a loop whose body never reaches a statement start, such as
//! `FOR i FROM 0 TO 0 STEP 0 DO ENDFOR`). With the 16,000 steps of a task alone, such
//! an input ran 160 million instructions (10 to 27 s instrumented: libFuzzer's "slow
//! units", 2026-11-28); tasks together now get 4,000 statements, about the work of
//! 16,000 instructions of ordinary code, and at most 40 million instructions.

use rapid_controller::{Controller, SystemExit};
use rapid_vm::Host;

/// Slices per input.
pub const SLICES: u64 = 16;

/// What one slice may charge: instructions for a task alone, statements for tasks
/// together.
pub fn slice_budget(tasks: usize) -> u64 {
    if tasks <= 1 {
        1_000
    } else {
        250
    }
}

/// Runs the controller's `tasks` tasks for at most [`SLICES`] slices.
pub fn run(controller: &mut Controller, host: &mut dyn Host, tasks: usize) {
    for _ in 0..SLICES {
        match controller.run(host, slice_budget(tasks)) {
            SystemExit::Budget => {}
            SystemExit::Wait(seconds) => controller.advance(seconds.min(10.0)),
            SystemExit::Ended | SystemExit::Stopped => break,
        }
    }
}

#[cfg(test)]
mod tests {
    use rapid_controller::{TaskKind, TaskSpec, TrustLevel};
    use rapid_sema::SourceInput;
    use rapid_vm::RecordingHost;

    use super::*;

    fn spec(idx: usize) -> TaskSpec {
        TaskSpec {
            name: if idx == 0 { "T_ROB1".to_owned() } else { format!("T_{idx}") },
            kind: TaskKind::Normal,
            trust: TrustLevel::SysFail,
            foreground: None,
            motion: idx == 0,
            robot: idx == 0,
            rmq: rapid_config::sys::Rmq::default(),
            shared_files: Vec::new(),
            robot_of: None,
        }
    }

    #[test]
    fn tasks_together_stop_after_their_statements_even_in_a_loop_of_no_statement() {
        // The slow unit's program, reduced: an empty FOR whose STEP is 0 never ends
        // and never reaches the start of a statement.
        let looping = "MODULE M0\n  PROC main()\n    VAR num n := 0;\n    FOR i FROM 0 TO n STEP n DO\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
        let idle = "MODULE M0\n  PROC main()\n  ENDPROC\nENDMODULE\n";
        let tasks = [looping, idle]
            .iter()
            .enumerate()
            .map(|(idx, text)| {
                let files = [SourceInput::from_text(format!("t{idx}.mod"), *text)];
                (spec(idx), rapid_controller::builtin_set::load(&files, "main").expect("the program loads"))
            })
            .collect();
        let mut controller = Controller::new(tasks, None).expect("the system starts");
        let mut host = RecordingHost::default();
        run(&mut controller, &mut host, 2);
        // Every slice ran its whole budget (the loop never ends), and no more.
        assert_eq!(controller.steps, SLICES * slice_budget(2));
        assert_eq!(SLICES * slice_budget(2), 4_000);
    }
}
