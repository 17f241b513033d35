//! A two-task system for the API tests: T_ROB1 moves the robot, T_OTHER waits for a
//! shared persistent and asks the operator on the pendant.

#![allow(dead_code)]

use rapid_controller::api::Session;
use rapid_controller::{Controller, TaskSpec};
use rapid_sema::SourceInput;

/// T_ROB1's module. Lines are counted by [`line_of`].
pub(crate) const ROBOT: &str = "MODULE MainModule
  PERS num shared := 0;
  VAR num reg1 := 5;
  VAR num bwd := 0;
  CONST num limit := 3;
  VAR num arr{3} := [1, 2, 3];
  PERS pos here := [1, 2, 3];
  VAR string name := \"abc\";
  VAR robtarget now;
  CONST robtarget p10 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget p20 := [[400, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveJ p10, v1000, fine, tool0;
    MoveL p20, v100, fine, tool0;
    Helper;
    reg1 := reg1 + 1;
    now := CRobT(\\Tool:=tool0);
    here := now.trans;
  ENDPROC
  PROC Helper()
    VAR num scale := 2;
    reg1 := reg1 * scale;
    reg1 := reg1 + 100;
  BACKWARD
    bwd := bwd + 1;
  ENDPROC
ENDMODULE
";

/// T_OTHER's module.
pub(crate) const OTHER: &str = "MODULE Other
  PERS num shared := 0;
  VAR num got := 0;
  VAR num key := 0;
  PROC main()
    WaitUntil shared > 0;
    got := shared;
    TPReadFK key, \"Continue?\", \"Yes\", \"No\", stEmpty, stEmpty, stEmpty;
    TPWrite \"key \" \\Num:=key;
  ENDPROC
ENDMODULE
";

/// The 1-based line of `text` that contains `needle` first.
pub(crate) fn line_of(text: &str, needle: &str) -> u32 {
    match text.lines().position(|l| l.contains(needle)) {
        Some(at) => at as u32 + 1,
        None => panic!("`{needle}` is not in the module"),
    }
}

fn spec(name: &str, motion: bool) -> TaskSpec {
    TaskSpec::normal(name, motion)
}

fn load(path: &str, text: &str, options: &rapid_sema::Options) -> rapid_vm::Loaded {
    match rapid_controller::builtin_set::load_with(&[SourceInput::from_text(path, text)], "main", options) {
        Ok(loaded) => loaded,
        Err(err) => panic!("{path} does not load: {err:?}"),
    }
}

/// A session on the two-task system, booted (stopped, PP at main).
pub(crate) fn session() -> Session {
    let options = rapid_sema::Options::default();
    let tasks = vec![
        (spec("T_ROB1", true), load("T_ROB1/MainModule.mod", ROBOT, &options)),
        (spec("T_OTHER", false), load("T_OTHER/Other.mod", OTHER, &options)),
    ];
    match Controller::new(tasks, None) {
        Ok(controller) => Session::new(controller),
        Err(message) => panic!("{message}"),
    }
}

/// A session on one task of `text` with the digital signals `inputs` and `outputs`.
pub(crate) fn with_signals(text: &str, inputs: &[&str], outputs: &[&str]) -> Session {
    let typed = |names: &[&str], ty: &str| -> Vec<(String, String)> {
        names.iter().map(|n| ((*n).to_owned(), ty.to_owned())).collect()
    };
    let all: Vec<(String, String)> = typed(inputs, "signaldi").into_iter().chain(typed(outputs, "signaldo")).collect();
    let predefined =
        all.iter().map(|(name, ty)| rapid_sema::PredefinedData { name: name.clone(), type_name: ty.clone() }).collect();
    let options = rapid_sema::Options { predefined, ..rapid_sema::Options::default() };
    let loaded = load("T_ROB1/MainModule.mod", text, &options);
    let signals: String = all
        .iter()
        .map(|(n, ty)| {
            format!("\n      -Name \"{n}\" -SignalType \"{}\"\n", if ty == "signaldi" { "DI" } else { "DO" })
        })
        .collect();
    let eio = rapid_config::eio::read(&rapid_config::parse(&format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{signals}")));
    let io = match rapid_controller::boot::io_config::io_system(&eio) {
        Ok(io) => io,
        Err(message) => panic!("{message}"),
    };
    match Controller::new(vec![(spec("T_ROB1", true), loaded)], Some(io)) {
        Ok(controller) => Session::new(controller),
        Err(message) => panic!("{message}"),
    }
}
