//! I/O signals through the VM (§1.9, §2.10): AliasIO connects RAPID signal data to
//! signals of the I/O system, orders and reads act on it at the controller's time.
//! `rapid run` cannot configure signals yet, so the I/O system is built here.

use rapid_io::{AnalogRange, IoSystem, SignalDef, SignalKind};
use rapid_sema::SourceInput;
use rapid_signals::IoAccess;
use rapid_vm::{Exit, LoadError, Loaded, RecordingHost};

/// Loads with the language's built-ins and the I/O signals' (rapid-signals).
fn load(files: &[SourceInput], entry: &str) -> Result<Loaded, LoadError> {
    let set = std::sync::Arc::new(rapid_vm::builtins::Builtins::new(&[&rapid_signals::EXTENSION]));
    rapid_vm::load_in(files, entry, &rapid_sema::Options::default(), set)
}

/// do1, di1, go1 (8 bits), ao1 (logical 0..10).
fn io_system() -> IoSystem {
    let mut go1 = SignalDef::new("go1", SignalKind::GO);
    go1.group_bits = 8;
    let mut ao1 = SignalDef::new("ao1", SignalKind::AO);
    ao1.analog =
        Some(AnalogRange { logical_min: 0.0, logical_max: 10.0, physical_min: 0.0, physical_max: 10.0, bits: 0 });
    let defs = vec![SignalDef::new("do1", SignalKind::DO), SignalDef::new("di1", SignalKind::DI), go1, ao1];
    match IoSystem::new(defs, Vec::new()) {
        Ok(io) => io,
        Err(err) => panic!("the test configuration is valid: {err:?}"),
    }
}

/// Runs `program` to its end with the I/O system above; the pendant lines.
fn run(program: &str) -> Vec<String> {
    run_with(program, &[])
}

/// Runs `program` to its end with the I/O system above and `stimulus` (time, signal
/// name, value) for its inputs; the pendant lines.
fn run_with(program: &str, stimulus: &[(f64, &str, f64)]) -> Vec<String> {
    let mut loaded = match load(&[SourceInput::from_text("m.mod", program)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("the program loads: {err:?}"),
    };
    let system = io_system();
    let io = loaded.vm.resources_mut().io_mut();
    for &(at, name, value) in stimulus {
        io.stimulus.push_back((at, system.id(name).expect("a configured signal"), value));
    }
    io.system = Some(system);
    let mut host = RecordingHost::default();
    for _ in 0..1_000 {
        match loaded.vm.run(&mut host, 100_000) {
            Exit::Wait(seconds) => loaded.vm.time += seconds,
            Exit::Done => return host.lines,
            other => panic!("the program ended with {other:?}; output {:?}", host.lines),
        }
    }
    panic!("the program did not end")
}

#[test]
fn orders_and_reads_follow_the_controller_clock() {
    // Hand-worked from §1.9/§2.10: Set/InvertDO act at once; PulseDO \PLength:=0.5 is
    // high until 0.5 s later; SetDO \SDelay:=1 changes the output 1 s later.
    let lines = run(r#"MODULE m
VAR signaldo lamp;
PROC main()
  AliasIO "do1", lamp;
  TPWrite "start " \Num:=lamp;
  Set lamp;
  TPWrite "set " \Num:=lamp;
  InvertDO lamp;
  TPWrite "inverted " \Num:=lamp;
  PulseDO \PLength:=0.5, lamp;
  TPWrite "pulse " \Num:=lamp;
  WaitTime 0.4;
  TPWrite "at 0.4 " \Num:=lamp;
  WaitTime 0.2;
  TPWrite "at 0.6 " \Num:=lamp;
  SetDO \SDelay:=1, lamp, 1;
  TPWrite "ordered " \Num:=lamp;
  WaitTime 1.1;
  TPWrite "after the delay " \Num:=lamp;
  Reset lamp;
  TPWrite "reset " \Num:=lamp;
ENDPROC
ENDMODULE
"#);
    let expected = [
        "start 0",
        "set 1",
        "inverted 0",
        "pulse 1",
        "at 0.4 1",
        "at 0.6 0",
        "ordered 0",
        "after the delay 1",
        "reset 0",
    ];
    assert_eq!(lines, expected);
}

#[test]
fn groups_analog_outputs_inputs_and_their_errors() {
    // go1 has 8 bits: 255 is the largest value, 256 raises ERR_GO_LIM; ao1's logical
    // range is 0..10, so 12 raises ERR_AO_LIM; di1 is 0 (its default).
    let lines = run(r#"MODULE m
VAR signalgo code;
VAR signalao speed;
VAR signaldi part;
PROC main()
  AliasIO "go1", code;
  AliasIO "ao1", speed;
  AliasIO "di1", part;
  SetGO code, 255;
  TPWrite "code " \Num:=code;
  TPWrite "code as dnum " \Dnum:=GOutputDnum(code);
  TPWrite "GOutput " \Num:=GOutput(code);
  SetAO speed, 2.5;
  TPWrite "speed " \Num:=speed;
  TPWrite "part " \Bool:=TestDI(part);
  TPWrite "valid " \Bool:=ValidIO(part);
  SetGO code, 256;
  SetAO speed, 12;
  TPWrite "code still " \Num:=code;
ERROR
  IF ERRNO = ERR_GO_LIM TPWrite "ERR_GO_LIM";
  IF ERRNO = ERR_AO_LIM TPWrite "ERR_AO_LIM";
  TRYNEXT;
ENDPROC
ENDMODULE
"#);
    let expected = [
        "code 255",
        "code as dnum 255",
        "GOutput 255",
        "speed 2.5",
        "part FALSE",
        "valid TRUE",
        "ERR_GO_LIM",
        "ERR_AO_LIM",
        "code still 255",
    ];
    assert_eq!(lines, expected);
}

#[test]
fn alias_io_errors_and_unconnected_signals() {
    // AliasIO: an unknown signal name → ERR_ALIASIO_DEF; a DI onto signaldo data →
    // ERR_ALIASIO_TYPE; unconnected data → ERR_NO_ALIASIO_DEF on use; AliasIOReset
    // disconnects (manual §1.9, AliasIO).
    let lines = run(r#"MODULE m
VAR signaldo lamp;
VAR signaldo other;
PROC main()
  AliasIO "nosuch", lamp;
  AliasIO "di1", lamp;
  Set lamp;
  TPWrite "valid " \Bool:=ValidIO(lamp);
  AliasIO "do1", lamp;
  AliasIO lamp, other;
  Set other;
  TPWrite "lamp through other " \Num:=lamp;
  AliasIOReset lamp;
  Reset lamp;
ERROR
  IF ERRNO = ERR_ALIASIO_DEF TPWrite "ERR_ALIASIO_DEF";
  IF ERRNO = ERR_ALIASIO_TYPE TPWrite "ERR_ALIASIO_TYPE";
  IF ERRNO = ERR_NO_ALIASIO_DEF TPWrite "ERR_NO_ALIASIO_DEF";
  TRYNEXT;
ENDPROC
ENDMODULE
"#);
    let expected = [
        "ERR_ALIASIO_DEF",
        "ERR_ALIASIO_TYPE",
        "ERR_NO_ALIASIO_DEF",
        "valid FALSE",
        "lamp through other 1",
        "ERR_NO_ALIASIO_DEF",
    ];
    assert_eq!(lines, expected);
}

#[test]
fn waits_end_when_the_signal_changes_or_time_runs_out() {
    // di1 becomes 1 at 1.5 s. WaitDI with \MaxTime:=1 and \TimeFlag gives up at 1 s
    // (flag TRUE, no error); the next WaitDI ends exactly at 1.5 s (flag FALSE); WaitGO
    // on go1 (still 0) with \MaxTime:=0.5 raises ERR_WAIT_MAXTIME at 2 s and stores the
    // value at timeout; WaitDO sees a pulse end at its scheduled time.
    let lines = run_with(
        r#"MODULE m
VAR signaldi part;
VAR signalgo code;
VAR signaldo lamp;
VAR clock c;
VAR bool late;
VAR num seen := -1;
PROC main()
  AliasIO "di1", part;
  AliasIO "go1", code;
  AliasIO "do1", lamp;
  ClkStart c;
  WaitDI part, 1 \MaxTime:=1 \TimeFlag:=late;
  TPWrite "gave up " \Bool:=late;
  TPWrite "at " \Num:=ClkRead(c);
  WaitDI part, 1 \MaxTime:=5 \TimeFlag:=late;
  TPWrite "in time " \Bool:=NOT late;
  TPWrite "at " \Num:=ClkRead(c);
  WaitGO code \GT, 3 \MaxTime:=0.5 \ValueAtTimeout:=seen;
  TPWrite "not reached";
ERROR
  IF ERRNO = ERR_WAIT_MAXTIME THEN
    TPWrite "ERR_WAIT_MAXTIME, value " \Num:=seen;
    TPWrite "at " \Num:=ClkRead(c);
    PulseDO \PLength:=0.25, lamp;
    WaitDO lamp, 0;
    TPWrite "pulse over at " \Num:=ClkRead(c);
    RETURN;
  ENDIF
ENDPROC
ENDMODULE
"#,
        &[(1.5, "di1", 1.0)],
    );
    let expected =
        ["gave up TRUE", "at 1", "in time TRUE", "at 1.5", "ERR_WAIT_MAXTIME, value 0", "at 2", "pulse over at 2.25"];
    assert_eq!(lines, expected);
}

#[test]
fn signal_interrupts_run_their_trap_on_each_matching_change() {
    // ISignalDO lamp, 1: every change of do1 to 1 (Set, the start of a pulse) starts the
    // trap before the next instruction; changes to 0 do not.
    let lines = run(r#"MODULE m
VAR signaldo lamp;
VAR intnum on_lamp;
VAR num rises := 0;
PROC main()
  AliasIO "do1", lamp;
  CONNECT on_lamp WITH lamp_trap;
  ISignalDO lamp, 1, on_lamp;
  Set lamp;
  TPWrite "after Set";
  Reset lamp;
  PulseDO \PLength:=0.5, lamp;
  WaitTime 1;
  TPWrite "rises " \Num:=rises;
ENDPROC
TRAP lamp_trap
  rises := rises + 1;
  TPWrite "lamp rose";
ENDTRAP
ENDMODULE
"#);
    assert_eq!(lines, ["lamp rose", "after Set", "lamp rose", "rises 2"]);
}

#[test]
fn group_interrupts_run_on_every_change() {
    // ISignalGO: each change of go1's value starts the trap; setting the same value
    // again is no change.
    let lines = run(r#"MODULE m
VAR signalgo code;
VAR intnum on_code;
PROC main()
  AliasIO "go1", code;
  CONNECT on_code WITH code_trap;
  ISignalGO code, on_code;
  SetGO code, 5;
  SetGO code, 5;
  SetGO code, 7;
  TPWrite "done";
ENDPROC
TRAP code_trap
  TPWrite "code now " \Num:=code;
ENDTRAP
ENDMODULE
"#);
    assert_eq!(lines, ["code now 5", "code now 7", "done"]);
}
