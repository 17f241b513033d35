//! The controller state across PP to Main: the active tool, work object and payload
//! go back to tool0, wobj0 and load0 (the start-up state of §1.17 / SYS_RESET),
//! while the operating mode and the operator's speed override are the controller's,
//! not the program's, and stay. A conformance program runs only one cycle, so this
//! needs the API. (That only manual reduced speed limits the TCP is rapid-vm's
//! `tests/controller.rs`.)

use rapid_robot::RobotResources;
use rapid_sema::SourceInput;
use rapid_vm::builtins::controller::{ControllerState, OpMode};
use rapid_vm::{Exit, RecordingHost};

/// Loads with the language's built-ins and the robot's (GripLoad, the motion
/// settings).
fn load(files: &[SourceInput], entry: &str) -> Result<rapid_vm::Loaded, rapid_vm::LoadError> {
    let set = std::sync::Arc::new(rapid_vm::builtins::Builtins::new(&[&rapid_robot::EXTENSION]));
    rapid_vm::load_in(files, entry, &rapid_sema::Options::default(), set)
}

const PROGRAM: &str = r#"MODULE t
PERS num runs := 0;
PERS tooldata tGun := [TRUE, [[0, 0, 200], [1, 0, 0, 0]], [3, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
PERS wobjdata wFix := [FALSE, TRUE, "", [[500, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
PERS loaddata lPart := [2, [0, 0, 10], [1, 0, 0, 0], 0, 0, 0];
PERS tooldata tRead := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
PERS wobjdata wRead := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
PERS loaddata lRead := [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0];
VAR string tool;
VAR string wobj;
VAR string payload;
PROC main()
  runs := runs + 1;
  GetSysData tRead \ObjectName:=tool;
  GetSysData wRead \ObjectName:=wobj;
  GetSysData lRead \ObjectName:=payload;
  TPWrite "run " + ValToStr(runs) + ": " + tool + " " + wobj + " " + payload;
  TPWrite "mode " + ValToStr(OpMode()) + " override " + ValToStr(CSpeedOverride());
  IF runs = 1 THEN
    SetSysData tGun;
    SetSysData wRead \ObjectName:="wFix";
    GripLoad lPart;
  ENDIF
ENDPROC
ENDMODULE
"#;

#[test]
fn pp_to_main_activates_tool0_wobj0_load0_and_keeps_the_mode() {
    let loaded = match load(&[SourceInput::from_text("t.mod", PROGRAM)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let (mut machine, entry) = (loaded.vm, loaded.entry);
    machine.resources_mut().controller = ControllerState::new(OpMode::ManualReduced, 30.0);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    assert!(machine.resources().motion().active.iter().all(Option::is_some));
    machine.pp_to_main(&mut host, entry).expect("pp to main");
    assert!(machine.resources().motion().active.iter().all(Option::is_none));
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    // OP_MAN_PROG is 2 (catalogue symnum).
    let expected = ["run 1: tool0 wobj0 load0", "mode 2 override 30", "run 2: tool0 wobj0 load0", "mode 2 override 30"];
    assert_eq!(host.lines, expected);
    assert_eq!(machine.resources_mut().controller.tcp_speed_limit(), Some(250.0));
}
