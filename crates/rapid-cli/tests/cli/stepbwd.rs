//! StepBwdPath from a RESTART event routine: a PLC stops the program during a MoveL
//! through a system input and starts it again; the RESTART routine steps the robot
//! back along its path, and the path goes on from where it stopped.
//!
//! Timing model (as in `system_signals.rs`): a 100 mm MoveL from x = 300 at v100 with
//! the IRB 120's 10 m/s² path acceleration speeds up for 0.01 s over 0.5 mm, so the TCP
//! is at x = 300.5 + 100 (t - 0.01) while it cruises; a stop point ends 0.05 s after the
//! robot stands (the fine settle time). A program stop stops the robot at the instant.

use std::fs;
use std::path::Path;
use std::process::Output;

use crate::fixture::{rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("stepbwd", name)
}

/// A one-task cell running `module`, with diStart/diStop as system inputs, doMoving,
/// and `on_restart` as the RESTART event routine; run with `stimulus`.
fn run_cell(dir: &Path, module: &str, stimulus: &str) -> Output {
    let root = dir.join("cell");
    fs::create_dir_all(root.join("RAPID/TASK1/PROGMOD")).expect("task folder");
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    fs::write(root.join("RAPID/TASK1/PROGMOD/Move.mod"), module).expect("module");
    let eio = "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"diStart\" -SignalType \"DI\"\n\n      \
               -Name \"diStop\" -SignalType \"DI\"\n\n      -Name \"doMoving\" -SignalType \"DO\"\n#\nSYSSIG_IN:\n\n      \
               -Signal \"diStart\" -Action \"Start\"\n\n      -Signal \"diStop\" -Action \"Stop\"\n";
    fs::write(root.join("SYSPAR/EIO.cfg"), eio).expect("EIO.cfg");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n#\n\
               CAB_EXEC_HOOKS:\n\n      -Routine \"on_restart\" -Shelf \"RESTART\" -Task \"T_ROB1\"\n";
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    fs::write(dir.join("plc.stim"), stimulus).expect("stimulus");
    rapid_in(dir, &["run", "--quiet", "--robot", "IRB120-3/0.58", "--stimulus", "plc.stim", "cell"])
}

/// The MoveL, and a RESTART routine with `restart` in it.
fn module(restart: &str) -> String {
    format!(
        "MODULE Move
  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR clock c;
  PROC main()
    MoveJ p0, v1000, fine, tool0;
    ClkStart c;
    SetDO doMoving, 1;
    MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
    TPWrite \"MoveL: \" + NumToStr(ClkRead(c), 2);
  ENDPROC
  PROC on_restart()
    VAR pos at;
{restart}
  ENDPROC
ENDMODULE
"
    )
}

const PLC: &str = "when doMoving = 1 after 0.5 s set diStop 1\nwhen diStop = 1 after 2 s set diStart 1\n";

#[test]
fn the_robot_steps_back_30_mm_and_the_path_goes_on_from_the_stop() {
    let dir = scratch("step");
    // Stopped 0.5 s into the MoveL at x = 300.5 + 100 · 0.49 = 349.5; started at 2.5 s.
    // StepBwdPath 30, 1: speed min(30 / 1, 100, 250) = 30 mm/s; 30 mm back to x = 319.5
    // takes 30 / 30 + 30 / 10000 (the ramps) + 0.05 (stop point) = 1.053 s: the routine
    // reads x 319.5 at 3.553 s. At the start the robot goes forward to x = 349.5 at the
    // segment's 100 mm/s: 30 / 100 + 100 / 10000 + 0.05 = 0.36 s, so the path is
    // (3.553 - 0.5) + 0.36 = 3.413 s late and the MoveL ends at 1.06 + 3.413 = 4.473 s.
    let restart = "    StepBwdPath 30, 1;\n    at := CPos();\n    \
                   TPWrite \"back at x \" + NumToStr(at.x, 1) + \" at \" + NumToStr(ClkRead(c), 2);";
    let out = run_cell(&dir, &module(restart), PLC);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "back at x 319.5 at 3.55\nMoveL: 4.47\n");
}

#[test]
fn a_step_beyond_the_segment_raises_err_bwdlimit() {
    let dir = scratch("limit");
    // 49.5 mm of the segment were done at the stop: 30 mm back is allowed, 30 more
    // (60 in all) is beyond its start: ERR_BWDLIMIT, and the robot stays at x = 319.5.
    let restart = "    StepBwdPath 30, 1;\n    StepBwdPath 30, 1;\n  ERROR\n    IF ERRNO = ERR_BWDLIMIT THEN\n      \
                   at := CPos();\n      TPWrite \"ERR_BWDLIMIT at x \" + NumToStr(at.x, 1);\n      TRYNEXT;\n    ENDIF";
    let out = run_cell(&dir, &module(restart), PLC);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "ERR_BWDLIMIT at x 319.5\nMoveL: 4.47\n");
}
