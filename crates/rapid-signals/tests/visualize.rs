//! `\Visualize` on the wait instructions (RW 6): the message box is shown through the
//! pendant host while the wait runs, and the wait ends exactly as without it.

use rapid_io::{IoSystem, SignalDef, SignalKind};
use rapid_sema::SourceInput;
use rapid_signals::IoAccess;
use rapid_vm::{Exit, LoadError, Loaded, RecordingHost};

/// Loads with the language's built-ins and the I/O signals' (rapid-signals).
fn load(files: &[SourceInput], entry: &str) -> Result<Loaded, LoadError> {
    let set = std::sync::Arc::new(rapid_vm::builtins::Builtins::new(&[&rapid_signals::EXTENSION]));
    rapid_vm::load_in(files, entry, &rapid_sema::Options::default(), set)
}

/// di1 (the input waited for), gi1 (4 bits), ui1 (the box's \UIActiveSignal).
fn io_system() -> IoSystem {
    let mut gi1 = SignalDef::new("gi1", SignalKind::GI);
    gi1.group_bits = 4;
    let defs = vec![SignalDef::new("di1", SignalKind::DI), gi1, SignalDef::new("ui1", SignalKind::DO)];
    match IoSystem::new(defs, Vec::new()) {
        Ok(io) => io,
        Err(err) => panic!("the test configuration is valid: {err:?}"),
    }
}

/// What a run shows: the pendant lines, the boxes (text, opened) and the changes of
/// ui1 as (time, value).
struct Shown {
    lines: Vec<String>,
    boxes: Vec<(String, bool)>,
    ui: Vec<(f64, f64)>,
}

fn run(program: &str, stimulus: &[(f64, &str, f64)]) -> Shown {
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
    for _ in 0..10_000 {
        match loaded.vm.run(&mut host, 100_000) {
            Exit::Wait(seconds) => loaded.vm.time += seconds,
            Exit::Done => {
                let changes =
                    loaded.vm.resources().io().system.as_ref().map(|s| s.changes().to_vec()).unwrap_or_default();
                let ui = changes.iter().filter(|c| &*c.signal == "ui1").map(|c| (c.time, c.new)).collect();
                return Shown { lines: host.lines, boxes: host.boxes, ui };
            }
            other => panic!("the program ended with {other:?}; output {:?}", host.lines),
        }
    }
    panic!("the program did not end")
}

const HEADER: &str = "MODULE m
VAR signaldi start;
VAR signalgi code;
VAR signaldo busy;
VAR clock clk;
VAR bool late;
VAR string lines{2} := [\"Load the part\", \"then press start\"];
PROC main()
  AliasIO \"di1\", start;
  AliasIO \"gi1\", code;
  AliasIO \"ui1\", busy;
  ClkStart clk;
";

fn program(body: &str) -> String {
    format!("{HEADER}{body}\n  TPWrite \"t=\" \\Num:=Round(ClkRead(clk) \\Dec:=1);\nENDPROC\nENDMODULE\n")
}

#[test]
fn waitdi_shows_its_box_until_the_signal_changes() {
    let shown = run(
        &program(
            "  WaitDI start, 1 \\Visualize \\Header:=\"Waiting\" \\Message:=\"Press start\" \\UIActiveSignal:=busy;",
        ),
        &[(2.0, "di1", 1.0)],
    );
    // The wait ends when di1 goes to 1 at 2 s, as without \Visualize.
    assert_eq!(shown.lines, ["t=2"]);
    let text = "Waiting\nPress start".to_string();
    assert_eq!(shown.boxes, [(text.clone(), true), (text, false)]);
    // \UIActiveSignal: 1 while the box is shown (from 0 s), 0 when it closes (2 s).
    assert_eq!(shown.ui, [(0.0, 1.0), (2.0, 0.0)]);
}

#[test]
fn a_wait_that_need_not_wait_shows_no_box() {
    let shown = run(&program("  WaitDI start, 0 \\Visualize \\Message:=\"never shown\";"), &[]);
    assert_eq!(shown.lines, ["t=0"]);
    assert!(shown.boxes.is_empty(), "{:?}", shown.boxes);
}

#[test]
fn visualize_time_closes_the_box_while_the_wait_goes_on() {
    // The box closes after 1 s; the wait goes on to 3 s when di1 changes.
    let shown = run(
        &program("  WaitUntil start = 1 \\Visualize \\MsgArray:=lines \\VisualizeTime:=1 \\UIActiveSignal:=busy;"),
        &[(3.0, "di1", 1.0)],
    );
    assert_eq!(shown.lines, ["t=3"]);
    let text = "Load the part\nthen press start".to_string();
    assert_eq!(shown.boxes, [(text.clone(), true), (text, false)]);
    assert_eq!(shown.ui.len(), 2, "{:?}", shown.ui);
    assert_eq!(shown.ui[0], (0.0, 1.0));
    // WaitUntil looks every 0.1 s (its PollRate), so the box closes at the first look
    // from 1 s on.
    assert!((shown.ui[1].0 - 1.0).abs() < 0.11 && shown.ui[1].1 == 0.0, "{:?}", shown.ui);
}

#[test]
fn the_box_closes_when_max_time_runs_out() {
    let shown = run(
        &program(
            "  WaitGI code, 5 \\MaxTime:=1.5 \\Visualize \\Header:=\"Code\";\n\
             ERROR\n  IF ERRNO = ERR_WAIT_MAXTIME THEN\n    TPWrite \"timeout\";\n    TRYNEXT;\n  ENDIF\n",
        )
        .replace("\n  TPWrite \"t=\" \\Num:=Round(ClkRead(clk) \\Dec:=1);\nENDPROC", "\nENDPROC"),
        &[],
    );
    assert_eq!(shown.lines, ["timeout"]);
    assert_eq!(shown.boxes, [("Code".to_string(), true), ("Code".to_string(), false)]);
}

#[test]
fn waituntil_with_time_flag_closes_its_box() {
    let shown = run(
        &program("  WaitUntil start = 1 \\MaxTime:=0.5 \\TimeFlag:=late \\Visualize \\Header:=\"Slow\";\n  TPWrite \"late \" \\Bool:=late;"),
        &[],
    );
    assert_eq!(shown.lines, ["late TRUE", "t=0.5"]);
    assert_eq!(shown.boxes, [("Slow".to_string(), true), ("Slow".to_string(), false)]);
}
