//! The tool and work object frames a move and its read-back go through, with values
//! worked out by hand: a tool 100 mm along the flange's z axis, a work object whose
//! user frame is 250 mm along the world's x axis, and a target 100 mm along the work
//! object's x axis and 400 mm up, the tool pointing down (orient [0, 0, 1, 0]: half a
//! turn about y, which takes z to -z).
//!
//! - In the work object with the tool, CRobT reads the target back: (100, 0, 400).
//! - In the world with the tool: the user frame adds 250 mm in x: (350, 0, 400).
//! - The flange (tool0) is 100 mm back along the tool's z axis, which points down:
//!   100 mm above the TCP, (350, 0, 500), with the same orientation.
//! - A fine point is reached exactly: CJointT after the move is where CalcJointT puts
//!   the target.

use rapid_sema::SourceInput;
use rapid_vm::{Exit, RecordingHost};

const PROGRAM: &str = r#"MODULE t
PERS tooldata tPen := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
PERS wobjdata wTable := [FALSE, TRUE, "", [[250, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
CONST robtarget pDown := [[100, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
PROC show(robtarget p)
  TPWrite ValToStr(Round(p.trans.x \Dec:=1)) + " " + ValToStr(Round(p.trans.y \Dec:=1)) + " " + ValToStr(Round(p.trans.z \Dec:=1))
    + " " + ValToStr(Round(Abs(p.rot.q3) \Dec:=3));
ENDPROC
PROC main()
  VAR jointtarget planned;
  VAR jointtarget reached;
  ConfJ \Off;
  ConfL \Off;
  MoveJ pDown, v1000, fine, tPen \WObj:=wTable;
  show CRobT(\Tool:=tPen \WObj:=wTable);
  show CRobT(\Tool:=tPen \WObj:=wobj0);
  show CRobT(\Tool:=tool0 \WObj:=wobj0);
  planned := CalcJointT(pDown, tPen \WObj:=wTable);
  reached := CJointT();
  TPWrite ValToStr(Abs(planned.robax.rax_1 - reached.robax.rax_1) < 0.001 AND Abs(planned.robax.rax_5 - reached.robax.rax_5) < 0.001);
ENDPROC
ENDMODULE
"#;

/// Loads with the language's built-ins and the robot's.
fn load(files: &[SourceInput], entry: &str) -> Result<rapid_vm::Loaded, rapid_vm::LoadError> {
    let set = std::sync::Arc::new(rapid_vm::builtins::Builtins::new(&[&rapid_robot::EXTENSION]));
    rapid_vm::load_in(files, entry, &rapid_sema::Options::default(), set)
}

#[test]
fn a_read_back_goes_through_the_tool_and_the_work_object() {
    let loaded = match load(&[SourceInput::from_text("t.mod", PROGRAM)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let mut machine = loaded.vm;
    let mut host = RecordingHost::default();
    // Each run returns at the move's wait; the clock moves on by it (bounded: the
    // program makes one move).
    let mut exit = Exit::Budget;
    for _ in 0..1_000 {
        exit = machine.run(&mut host, 1_000_000);
        match exit {
            Exit::Wait(seconds) => machine.time += seconds,
            Exit::Budget => {}
            _ => break,
        }
    }
    assert_eq!(exit, Exit::Done, "{:?}", host.lines);
    assert_eq!(host.lines, ["100 0 400 1", "350 0 400 1", "350 0 500 1", "TRUE"]);
}
