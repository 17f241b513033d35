//! Path levels and restarts end to end (§1.8, §2.2.6): StorePath/RestoPath around
//! moves on path level 2, StartMove's regain and ERR_PATHDIST, StartMoveRetry,
//! StopMoveReset, `\T` and `\Inpos` on moves, and the path recorder.
//!
//! Times are worked out by hand from the timing model of the default IRB 120: the
//! TCP accelerates at 10 000 mm/s², so a stop-to-stop MoveL of L mm at v mm/s takes
//! L/v + v/10 000 s, and a `fine` point stands 0.05 s more (settle).

use std::fs;
use std::path::Path;

use crate::fixture::{rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("path", name)
}

/// Writes backup `sys` in `dir`: one motion task running `module`, and the signals.
fn system(dir: &Path, module: &str, eio_signals: &str) {
    let root = dir.join("sys");
    let folder = root.join("RAPID/TASK1/PROGMOD");
    fs::create_dir_all(&folder).expect("task folder");
    fs::write(folder.join("Main.mod"), module).expect("module");
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n";
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    fs::write(root.join("SYSPAR/EIO.cfg"), format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{eio_signals}"))
        .expect("EIO.cfg");
}

const SIGNALS: &str = "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"diStop\" -SignalType \"DI\"\n";

/// Runs `module` with diStop rising `after` seconds after doStart; stdout.
fn run_stopped(name: &str, module: &str, after: f64) -> (Option<i32>, String, String) {
    let dir = scratch(name);
    system(&dir, module, SIGNALS);
    fs::write(dir.join("stop.stim"), format!("when doStart = 1 after {after} s set diStop 1\n")).expect("stimulus");
    let out = rapid_in(&dir, &["run", "--quiet", "--stimulus", "stop.stim", "sys"]);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

const P0: &str = "CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];";

/// The program of the StorePath tests: a 100 mm MoveL at v100 that diStop interrupts,
/// with `trap` as the TRAP's body.
fn interrupted_move(trap: &str) -> String {
    format!(
        "MODULE S\n  {P0}\n  VAR intnum stopint;\n  VAR clock c;\n  PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    \
         CONNECT stopint WITH on_stop;\n    ISignalDI diStop, 1, stopint;\n    ClkStart c;\n    SetDO doStart, 1;\n    \
         MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;\n    \
         TPWrite \"arrived after \" + NumToStr(ClkRead(c), 2) + \" at level \" \\Num:=PathLevel();\n    IDelete stopint;\n  \
         ENDPROC\n  TRAP on_stop\n    VAR robtarget here;\n{trap}  ENDTRAP\nENDMODULE\n"
    )
}

#[test]
fn storepath_moves_on_level_2_and_the_base_path_goes_on_after_restopath() {
    // The 100 mm MoveL at v100 takes 1.01 s + 0.05 s settle = 1.06 s. At 0.3 s the trap
    // stops it (0.5 mm in the first 0.01 s, then 0.29 s at 100 mm/s: x = 329.5) and
    // stores the path. On level 2 the robot goes 50 mm up and back, each 50/100 +
    // 100/10 000 + 0.05 = 0.56 s: back at 0.3 + 1.12 = 1.42 s, where RestoPath and
    // StartMove let the base path go on; it stood 1.12 s, so it ends at 1.06 + 1.12 =
    // 2.18 s.
    let trap = "    StopMove;\n    StorePath;\n    TPWrite \"stored, level \" \\Num:=PathLevel();\n    \
                here := CRobT(\\Tool:=tool0);\n    TPWrite \"stopped at x \" \\Num:=here.trans.x;\n    \
                MoveL Offs(here, 0, 0, 50), v100, fine, tool0;\n    MoveL here, v100, fine, tool0;\n    \
                TPWrite \"back after \" + NumToStr(ClkRead(c), 2);\n    RestoPath;\n    \
                TPWrite \"restored, level \" \\Num:=PathLevel();\n    StartMove;\n";
    let (code, out, err) = run_stopped("storepath", &interrupted_move(trap), 0.3);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        out,
        "stored, level 2\nstopped at x 329.5\nback after 1.42\nrestored, level 1\narrived after 2.18 at level 1\n"
    );
}

#[test]
fn storepath_without_stopmove_lets_the_robot_finish_its_move_first() {
    // No StopMove: StorePath stops the base path at the end of the move the robot is
    // on, and waits there (1.06 s); the stop-move state is not set. Level 2 goes 50 mm up and back (0.56 s each) and
    // is back at 2.18 s; the base path has nothing left, so the move instruction main
    // waits on is done then.
    let trap = "    StorePath;\n    here := CRobT(\\Tool:=tool0);\n    \
                TPWrite \"stop-move state \" \\Bool:=IsStopMoveAct(\\FromMoveTask);\n    \
                TPWrite \"stored at x \" \\Num:=here.trans.x;\n    \
                TPWrite \"after \" + NumToStr(ClkRead(c), 2);\n    \
                MoveL Offs(here, 0, 0, 50), v100, fine, tool0;\n    MoveL here, v100, fine, tool0;\n    \
                RestoPath;\n    StartMove;\n";
    let (code, out, err) = run_stopped("storepath_no_stop", &interrupted_move(trap), 0.3);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(out, "stop-move state FALSE\nstored at x 400\nafter 1.06\narrived after 2.18 at level 1\n");
}

#[test]
fn startmove_takes_the_robot_back_to_its_path_first() {
    // Stopped at 0.3 s at x = 329.5, level 2 goes 50 mm up (0.56 s, at 0.86 s) and 45
    // mm down (0.45 + 0.01 + 0.05 = 0.51 s, at 1.37 s): 5 mm above the path, within
    // the 10 mm StartMove takes the robot back. The move back is a joint move at
    // 100 mm/s: 5/100 s cruising, a few ms to ramp its axes (about 1°, at most 250°/s
    // reached in 0.15 s: under 0.02 s) and the 0.05 s settle. The base path stood
    // 1.07 s plus that move: it ends between 1.06 + 1.07 + 0.10 = 2.23 s and 2.25 s.
    let trap = "    StopMove;\n    StorePath;\n    here := CRobT(\\Tool:=tool0);\n    \
                MoveL Offs(here, 0, 0, 50), v100, fine, tool0;\n    MoveL Offs(here, 0, 0, 5), v100, fine, tool0;\n    \
                RestoPath;\n    StartMove;\n";
    let module = interrupted_move(trap).replace("NumToStr(ClkRead(c), 2)", "NumToStr(ClkRead(c), 3)");
    let (code, out, err) = run_stopped("regain", &module, 0.3);
    assert_eq!(code, Some(0), "{err}");
    let time: f64 = out
        .strip_prefix("arrived after ")
        .and_then(|rest| rest.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("{out}"));
    assert!((2.23..=2.25).contains(&time), "{out}");
    assert!(out.ends_with(" at level 1\n"), "{out}");
}

#[test]
fn read_backs_follow_the_robot_back_to_its_path() {
    // As above: the robot stands 5 mm above its stopped path (z 405) when StartMove
    // takes it back. 0.04 s into the move back at 100 mm/s it has come part of the way:
    // neither still at z 405 nor already on the path at z 400.
    let trap = "    StopMove;\n    StorePath;\n    here := CRobT(\\Tool:=tool0);\n    \
                MoveL Offs(here, 0, 0, 50), v100, fine, tool0;\n    MoveL Offs(here, 0, 0, 5), v100, fine, tool0;\n    \
                RestoPath;\n    StartMove;\n    WaitTime 0.04;\n    here := CRobT(\\Tool:=tool0);\n    \
                TPWrite \"z \" + NumToStr(here.trans.z, 2);\n";
    let (code, out, err) = run_stopped("regain_read_back", &interrupted_move(trap), 0.3);
    assert_eq!(code, Some(0), "{err}");
    let z: f64 = out
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("z "))
        .and_then(|z| z.parse().ok())
        .unwrap_or_else(|| panic!("{out}"));
    assert!(z > 400.5 && z < 404.9, "z {z} during the move back\n{out}");
}

#[test]
fn the_path_recorder_backs_out_and_returns_in_a_trap() {
    // Recording from p0, the robot is stopped 0.3 s into the 100 mm move (x = 329.5).
    // On level 2 it goes back along the recorded line to p0 (29.5 mm: 0.295 + 0.01 +
    // 0.05 = 0.355 s, at 0.655 s) and forward again (at 1.01 s); the base path stood
    // 0.71 s, so the move main waits on ends at 1.06 + 0.71 = 1.77 s.
    let trap = "    VAR pos at;\n    StopMove;\n    StorePath;\n    IF PathRecValidBwd(\\ID:=start_id) THEN\n      \
                PathRecMoveBwd \\ID:=start_id;\n      at := CPos(\\Tool:=tool0);\n      \
                TPWrite \"back at \" + NumToStr(ClkRead(c), 3) + \" x \" \\Num:=at.x;\n      \
                PathRecMoveFwd;\n      at := CPos(\\Tool:=tool0);\n      \
                TPWrite \"forward at \" + NumToStr(ClkRead(c), 3) + \" x \" \\Num:=at.x;\n    ENDIF\n    \
                RestoPath;\n    StartMove;\n";
    let module = interrupted_move(trap)
        .replace("  VAR clock c;\n", "  VAR clock c;\n  VAR pathrecid start_id;\n")
        .replace("    ClkStart c;\n", "    PathRecStart start_id;\n    ClkStart c;\n")
        .replace("    VAR robtarget here;\n    VAR pos at;\n", "    VAR pos at;\n");
    let (code, out, err) = run_stopped("recorder", &module, 0.3);
    assert_eq!(code, Some(0), "{err}\n{module}");
    assert_eq!(out, "back at 0.655 x 300\nforward at 1.010 x 329.5\narrived after 1.77 at level 1\n");
}

#[test]
fn the_trace_names_the_level_2_moves_by_their_own_instructions() {
    // The conformance program motion_path_store_two_traps: main's 100 mm MoveL (line 40)
    // is stopped at 0.3 s by a trap whose MoveL up (line 19) takes 0.56 s; a later trap
    // moves down (line 26, 0.56 s), restores and restarts the path, whose rest takes
    // 1.06 − 0.3 = 0.76 s. At 4 ms a row, the trace names them in that order: 75, 140,
    // 140 and 190 rows (main's move was named all along before).
    let dir = scratch("trace_level_2");
    let program = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/conformance/motion_path_store_two_traps.mod");
    let trace = dir.join("trace.csv");
    let out = rapid_in(&dir, &["run", "--quiet", "--trace", trace.to_str().unwrap(), program.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let text = fs::read_to_string(&trace).expect("trace");
    let mut runs: Vec<(String, usize)> = Vec::new();
    for line in text.lines().skip(1) {
        let place = line.rsplit(':').next().unwrap_or("").to_owned();
        match runs.last_mut() {
            Some((last, n)) if *last == place => *n += 1,
            _ => runs.push((place, 1)),
        }
    }
    let lines: Vec<(&str, usize)> = runs.iter().skip(1).map(|(l, n)| (l.as_str(), *n)).collect();
    assert_eq!(lines, [("40", 75), ("19", 140), ("26", 140), ("40", 190)]);
}
