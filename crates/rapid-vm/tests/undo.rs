//! The UNDO context (manual §1.13) as an embedder sees it: STOP, BREAK, RAISE and RETURN
//! ignored there with an event-log warning placed at the statement, whether the UNDO
//! runs for EXIT or for "PP to Main", and whether the program runs in one go or one
//! instruction at a time. (The `rapid run` side is in tests/conformance/undo_ignores_*.)

use rapid_sema::SourceInput;
use rapid_vm::events::{EventKind, IGNORED_IN_UNDO, PROGRAM_DOMAIN};
use rapid_vm::{load, Exit, RecordingHost, Vm};

const SUB_STOPS: &str = "MODULE t
PROC cleanup()
  TPWrite \"cleanup\";
  Break;
  RAISE 4;
ENDPROC
PROC sub()
  TPWrite \"in sub\";
  Stop;
  TPWrite \"after stop\";
UNDO
  TPWrite \"undo sub 1\";
  Stop;
  RAISE 3;
  RETURN;
  cleanup;
  TPWrite \"undo sub 2\";
ENDPROC
PROC main()
  sub;
UNDO
  TPWrite \"undo main\";
ENDPROC
ENDMODULE";

fn load_vm(src: &str) -> (Vm, u32) {
    match load(&[SourceInput::from_text("t.mod", src)], "main") {
        Ok(loaded) => (loaded.vm, loaded.entry),
        Err(err) => panic!("load failed: {err:?}"),
    }
}

/// The (instruction word, routine, statement text) of each UNDO warning in the log.
fn undo_warnings(vm: &Vm, src: &str) -> Vec<(String, String, String)> {
    vm.event_log()
        .iter()
        .filter(|e| e.domain == PROGRAM_DOMAIN && e.number == IGNORED_IN_UNDO.0)
        .map(|e| {
            assert_eq!(e.kind, EventKind::Warning);
            assert_eq!(e.code(), 40901);
            let word = e.lines[0].split_whitespace().next().unwrap_or("").to_string();
            let place = e.place.as_ref().expect("a placed warning");
            let text = src[place.span.start as usize..place.span.end as usize].to_string();
            (word, place.routine.clone(), text)
        })
        .collect()
}

fn expected_warnings() -> Vec<(String, String, String)> {
    [
        ("STOP", "sub", "Stop;"),
        ("RAISE", "sub", "RAISE 3;"),
        ("RETURN", "sub", "RETURN;"),
        ("BREAK", "cleanup", "Break;"),
        ("RAISE", "cleanup", "RAISE 4;"),
    ]
    .iter()
    .map(|(w, r, t)| (w.to_string(), r.to_string(), t.to_string()))
    .collect()
}

#[test]
fn pp_to_main_runs_undo_handlers_that_ignore_stop_break_raise_and_return() {
    // The Stop in sub's body (not in UNDO) stops the program; PP to Main then runs
    // sub's UNDO handler and main's (§1.13), where nothing stops, raises or returns.
    let (mut machine, entry) = load_vm(SUB_STOPS);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 10_000), Exit::Stopped);
    machine.pp_to_main(&mut host, entry).expect("pp to main");
    assert_eq!(host.lines, vec!["in sub", "undo sub 1", "cleanup", "undo sub 2", "undo main"]);
    assert_eq!(undo_warnings(&machine, SUB_STOPS), expected_warnings());
}

#[test]
fn one_instruction_at_a_time_the_undo_context_is_the_same() {
    // EXIT instead of Stop; a budget of one instruction takes the general path for
    // every instruction, where a whole run takes the fast loop.
    let src = SUB_STOPS.replace("  Stop;\n  TPWrite \"after stop\";", "  EXIT;\n  TPWrite \"after stop\";");
    let (mut machine, _) = load_vm(&src);
    let mut host = RecordingHost::default();
    let mut budgets = 0;
    let exit = loop {
        match machine.run(&mut host, 1) {
            Exit::Budget => budgets += 1,
            other => break other,
        }
        assert!(budgets < 10_000, "the program must end");
    };
    assert_eq!(exit, Exit::Done);
    assert!(machine.ended_by_exit());
    assert_eq!(host.lines, vec!["in sub", "undo sub 1", "cleanup", "undo sub 2", "undo main"]);
    assert_eq!(undo_warnings(&machine, &src), expected_warnings());
}
