//! The interpreter as the controller drives it: resumable runs with a step budget,
//! waits that hand control back, two programs interleaved one step at a time, and
//! pendant answers from the host.

use rapid_sema::SourceInput;
use rapid_vm::{load, Exit, RecordingHost, Vm};

fn vm(src: &str) -> Vm {
    match load(&[SourceInput::from_text("t.mod", src)], "main") {
        Ok(loaded) => loaded.vm,
        Err(err) => panic!("load failed: {err:?}"),
    }
}

const COUNTER: &str =
    "MODULE t\nPROC main()\n  FOR i FROM 1 TO 3 DO\n    TPWrite \"line \" \\Num:=i;\n  ENDFOR\nENDPROC\nENDMODULE";

#[test]
fn a_run_can_stop_after_any_instruction_and_resume() {
    let mut machine = vm(COUNTER);
    let mut host = RecordingHost::default();
    let mut n_budget_exits = 0;
    loop {
        match machine.run(&mut host, 1) {
            Exit::Budget => n_budget_exits += 1,
            Exit::Done => break,
            other => panic!("unexpected exit {other:?}"),
        }
        assert!(n_budget_exits < 10_000, "the program must end");
    }
    assert_eq!(host.lines, vec!["line 1", "line 2", "line 3"]);
    assert!(n_budget_exits > 3, "one-step budgets must return to the caller repeatedly");
}

#[test]
fn two_programs_interleave_step_by_step() {
    let (mut a, mut b) = (vm(COUNTER), vm(&COUNTER.replace("line ", "other ")));
    let mut host = RecordingHost::default();
    let (mut a_done, mut b_done) = (false, false);
    while !(a_done && b_done) {
        if !a_done {
            a_done = a.run(&mut host, 1) == Exit::Done;
        }
        if !b_done {
            b_done = b.run(&mut host, 1) == Exit::Done;
        }
    }
    // Identical programs advanced one instruction each in turn: their writes alternate.
    let expected: Vec<String> = (1..=3).flat_map(|i| [format!("line {i}"), format!("other {i}")]).collect();
    assert_eq!(host.lines, expected);
}

#[test]
fn waits_hand_control_back_with_the_time_to_wait() {
    let mut machine =
        vm("MODULE t\nPROC main()\n  TPWrite \"a\";\n  WaitTime 1.5;\n  TPWrite \"b\";\nENDPROC\nENDMODULE");
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 1_000), Exit::Wait(1.5));
    assert_eq!(host.lines, vec!["a"]);
    machine.time += 1.5;
    assert_eq!(machine.run(&mut host, 1_000), Exit::Done);
    assert_eq!(host.lines, vec!["a", "b"]);
}

#[test]
fn pendant_dialogs_take_the_hosts_answers() {
    let src = "MODULE t\nPROC main()\n  VAR num n;\n  TPReadNum n, \"How many?\";\n  TPWrite \"n=\" \\Num:=n * 2;\nENDPROC\nENDMODULE";
    let mut machine = vm(src);
    let mut host = RecordingHost::default();
    host.answers.push_back("21".into());
    assert_eq!(machine.run(&mut host, 1_000), Exit::Done);
    assert_eq!(host.lines, vec!["n=42"]);

    let mut unanswered = vm(src);
    let mut host = RecordingHost::default();
    match unanswered.run(&mut host, 1_000) {
        Exit::Unhandled(u) => assert_eq!(u.error.name, "ERR_TP_NO_CLIENT"),
        other => panic!("expected ERR_TP_NO_CLIENT, got {other:?}"),
    }
}

#[test]
fn runaway_recursion_is_a_clean_stop() {
    let mut machine = vm("MODULE t\nPROC r()\n  r;\nENDPROC\nPROC main()\n  r;\nENDPROC\nENDMODULE");
    let mut host = RecordingHost::default();
    match machine.run(&mut host, u64::MAX) {
        Exit::Unhandled(u) => assert!(u.error.message.contains("nested routine calls"), "{}", u.error.message),
        other => panic!("expected a stop, got {other:?}"),
    }
}

#[test]
fn pp_to_main_reinitialises_variables_and_keeps_persistents() {
    // §1.2.2 start-up table: "PP to Main" initialises constants and variables; persistents
    // are unchanged.
    let src = "MODULE t\nPERS num p := 0;\nVAR num v := 0;\nPROC main()\n  p := p + 1;\n  v := v + 1;\n  TPWrite \"p=\" \\Num:=p;\n  TPWrite \"v=\" \\Num:=v;\nENDPROC\nENDMODULE";
    let loaded = match load(&[SourceInput::from_text("t.mod", src)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let (mut machine, entry) = (loaded.vm, loaded.entry);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 10_000), Exit::Done);
    machine.pp_to_main(&mut host, entry).expect("pp to main");
    assert_eq!(machine.run(&mut host, 10_000), Exit::Done);
    assert_eq!(host.lines, vec!["p=1", "v=1", "p=2", "v=1"]);
}

#[test]
fn a_stopped_program_continues_with_the_next_instruction() {
    let mut machine = vm("MODULE t\nPROC main()\n  TPWrite \"a\";\n  Stop;\n  TPWrite \"b\";\nENDPROC\nENDMODULE");
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 1_000), Exit::Stopped);
    assert_eq!(host.lines, vec!["a"]);
    assert_eq!(machine.run(&mut host, 1_000), Exit::Done);
    assert_eq!(host.lines, vec!["a", "b"]);
}

#[test]
fn pp_to_main_runs_the_undo_handlers_of_running_routines() {
    // §1.13: moving the program pointer to main while routines run executes their UNDO.
    let src = "MODULE t\nPROC sub()\n  TPWrite \"in sub\";\n  Stop;\nUNDO\n  TPWrite \"undo sub\";\nENDPROC\nPROC main()\n  sub;\nENDPROC\nENDMODULE";
    let loaded = match load(&[SourceInput::from_text("t.mod", src)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let (mut machine, entry) = (loaded.vm, loaded.entry);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 1_000), Exit::Stopped);
    machine.pp_to_main(&mut host, entry).expect("pp to main");
    assert_eq!(host.lines, vec!["in sub", "undo sub"]);
}

#[test]
fn exit_cycle_ends_the_cycle_after_undo() {
    let src = "MODULE t\nPROC main()\n  TPWrite \"a\";\n  ExitCycle;\n  TPWrite \"never\";\nUNDO\n  TPWrite \"undo main\";\nENDPROC\nENDMODULE";
    let mut machine = vm(src);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 1_000), Exit::CycleEnded);
    assert_eq!(host.lines, vec!["a", "undo main"]);
}

/// The manual's example 1 of §1.21, with TPWrite standing in for the moves.
const MOVE_TO: &str = "MODULE t\nPROC MoveTo()\n  TPWrite \"fwd p1\";\n  TPWrite \"fwd p2 p3\";\n  TPWrite \"fwd p4\";\nBACKWARD\n  TPWrite \"back p4\";\n  TPWrite \"back p2 p3\";\n  TPWrite \"back p1\";\nENDPROC\nPROC Plain()\n  TPWrite \"plain\";\nENDPROC\nPROC main()\n  TPWrite \"start\";\n  MoveTo;\n  Plain;\n  Stop;\n  TPWrite \"end\";\nENDPROC\nENDMODULE";

#[test]
fn stepping_backward_runs_backward_handlers_and_refuses_what_the_manual_refuses() {
    use rapid_vm::{BackStep, BackwardRefusal};
    let mut machine = vm(MOVE_TO);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 10_000), Exit::Stopped);
    assert_eq!(host.lines, vec!["start", "fwd p1", "fwd p2 p3", "fwd p4", "plain"]);
    host.lines.clear();
    // Back over Stop (no backward meaning), then Plain has no BACKWARD handler.
    assert_eq!(machine.step_backward(&mut host), Ok(BackStep::Moved));
    assert_eq!(machine.step_backward(&mut host), Err(BackwardRefusal::NoBackwardHandler("Plain".into())));
    assert!(host.lines.is_empty());
}

#[test]
fn a_call_runs_backward_through_its_backward_handler() {
    use rapid_vm::{BackStep, BackwardRefusal};
    let src = MOVE_TO.replace("  Plain;\n", "");
    let mut machine = vm(&src);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 10_000), Exit::Stopped);
    host.lines.clear();
    assert_eq!(machine.step_backward(&mut host), Ok(BackStep::Moved));
    assert_eq!(machine.step_backward(&mut host), Ok(BackStep::RanBackwardHandler("MoveTo".into())));
    assert_eq!(host.lines, vec!["back p4", "back p2 p3", "back p1"]);
    assert_eq!(machine.step_backward(&mut host), Ok(BackStep::Moved));
    assert_eq!(machine.step_backward(&mut host), Err(BackwardRefusal::AtRoutineStart));
    // Running forward again from the start repeats the program's first lines.
    host.lines.clear();
    assert_eq!(machine.run(&mut host, 10_000), Exit::Stopped);
    assert_eq!(host.lines, vec!["start", "fwd p1", "fwd p2 p3", "fwd p4"]);
}

#[test]
fn backward_execution_does_not_leave_compound_statements() {
    use rapid_vm::BackwardRefusal;
    let mut machine = vm("MODULE t\nPROC main()\n  IF TRUE THEN\n    TPWrite \"in\";\n    Stop;\n    TPWrite \"still in\";\n  ENDIF\nENDPROC\nENDMODULE");
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 1_000), Exit::Stopped);
    assert_eq!(machine.step_backward(&mut host), Err(BackwardRefusal::InsideCompoundStatement));
}

#[test]
fn the_event_log_keeps_each_entry_with_its_domain_number_kind_and_time() {
    use rapid_vm::events::EventKind;
    let src = "MODULE t\nPROC main()\n  WaitTime 2;\n  ErrLog 4801 \\W, \"Hot\", \"Motor 3\", ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;\n  ErrWrite \"Stop\", \"Door open\";\nENDPROC\nENDMODULE";
    let mut machine = vm(src);
    let mut host = RecordingHost::default();
    loop {
        match machine.run(&mut host, 1000) {
            Exit::Wait(seconds) => machine.time += seconds,
            Exit::Done => break,
            other => panic!("unexpected exit {other:?}"),
        }
    }
    let log = machine.event_log();
    assert_eq!(log.len(), 2);
    assert_eq!((log[0].domain, log[0].number, log[0].kind, log[0].code()), (8, 4801, EventKind::Warning, 84801));
    assert_eq!((log[0].title.as_str(), log[0].lines.clone()), ("Hot", vec!["Motor 3".to_string()]));
    assert_eq!(log[0].time, 2.0, "logged after the 2 s wait");
    assert_eq!((log[1].code(), log[1].kind, log[1].title.as_str()), (80001, EventKind::Error, "Stop"));
    assert_eq!(host.lines, vec!["Stop", "Door open"], "ErrWrite also shows its lines on the pendant");
}

#[test]
fn an_error_nothing_handles_is_logged_in_the_program_domain() {
    let src = "MODULE t\nPROC main()\n  VAR num zero;\n  TPWrite \"x\" \\Num:=1 / zero;\nENDPROC\nENDMODULE";
    let mut machine = vm(src);
    let mut host = RecordingHost::default();
    let Exit::Unhandled(unhandled) = machine.run(&mut host, 1000) else { panic!("the division must fail") };
    let log = machine.event_log();
    assert_eq!(log.len(), 1);
    assert_eq!(log[0].domain, rapid_vm::events::PROGRAM_DOMAIN);
    assert_eq!(log[0].number as i32, unhandled.error.errno);
    assert!(log[0].title.contains("ERR_DIVZERO"), "title: {}", log[0].title);
    assert_eq!(log[0].lines, vec!["routine main".to_string()]);
}

/// §1.12: an error an ERROR handler takes still leaves a warning in the event log;
/// SkipWarn in the handler keeps it out.
#[test]
fn handled_errors_leave_a_warning_unless_the_handler_skips_it() {
    use rapid_vm::events::{EventKind, PROGRAM_DOMAIN};
    let src = "MODULE t
PROC main()
  VAR num zero;
  VAR num x;
  x := 1 / zero;
  x := 2 / zero;
  TPWrite \"done\";
ERROR
  IF x = 0 THEN
    x := 5;
    TRYNEXT;
  ENDIF
  SkipWarn;
  TRYNEXT;
ENDPROC
ENDMODULE";
    let mut machine = vm(src);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 10_000), Exit::Done);
    assert_eq!(host.lines, vec!["done"]);
    let log = machine.event_log();
    assert_eq!(log.len(), 1, "only the first division's warning stays: {log:?}");
    assert_eq!((log[0].domain, log[0].kind), (PROGRAM_DOMAIN, EventKind::Warning));
    assert!(log[0].title.contains("ERR_DIVZERO"), "title: {}", log[0].title);
}

#[test]
fn the_event_log_keeps_the_newest_entries_within_its_capacity() {
    use rapid_vm::events::LOG_CAPACITY;
    let src = "MODULE t
PROC main()
  FOR i FROM 1 TO 1500 DO
    ErrLog 4800, \"n\" + NumToStr(i, 0), ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
  ENDFOR
ENDPROC
ENDMODULE";
    let mut machine = vm(src);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 1_000_000), Exit::Done);
    let log = machine.event_log();
    assert!(log.len() <= LOG_CAPACITY && log.len() >= LOG_CAPACITY * 9 / 10, "{} entries", log.len());
    assert_eq!(log.last().map(|e| (e.title.as_str(), e.seq)), Some(("n1500", 1499)), "the newest is kept");
    assert!(log.windows(2).all(|w| w[1].seq == w[0].seq + 1), "consecutive, oldest dropped first");
}

#[test]
fn tpshow_reaches_the_host_and_refuses_unknown_windows() {
    let mut vm = vm("MODULE m\nPROC main()\n  TPShow TP_SCREENVIEWER;\n  TPShow TP_LATEST;\n  TPShow 7;\nERROR\n  IF ERRNO = ERR_ARGVALERR TPWrite \"ERR_ARGVALERR\";\n  RETURN;\nENDPROC\nENDMODULE\n");
    let mut host = RecordingHost::default();
    assert_eq!(vm.run(&mut host, 1_000), Exit::Done);
    // TP_SCREENVIEWER and TP_LATEST as the catalogue numbers them.
    assert_eq!(host.shown, [3, 2]);
    assert_eq!(host.lines, ["ERR_ARGVALERR"]);
}
