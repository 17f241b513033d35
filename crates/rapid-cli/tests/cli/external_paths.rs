//! External axes on the paths the program sets aside and takes back (§1.8, §2.2.6):
//! path level 2 after StorePath, RestoPath, and the path recorder, with the manifest
//! units of `external_fixture` (a track TRACK and a turntable STN1, full speed in 0.15 s).
//! Times worked by hand: a stop-to-stop move of d at cruise speed v with ramps of 0.15 s
//! takes d/v + 0.15 s, and a stop point adds 0.05 s of settle.

use std::fs;

use crate::external_fixture::{run, units_with_table, write_manifest, TRACK, UNITS};
use crate::fixture::{rapid, scratch_in, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("external_paths", name)
}

/// A project folder holding `rapid.toml` (one task, `extra` appended) and `main.mod`
/// with `body` as the statements of `main`.
fn project(name: &str, decls: &str, body: &str, extra: &str) -> Scratch {
    crate::external_fixture::project_at(scratch(name), decls, body, extra)
}

/// A project with the track and turntable, a DO doStart and a DI diStop that rises
/// 0.5 s after doStart, and `module` as its program; stdout, stderr and the exit code.
fn run_stopped(name: &str, module: &str) -> (String, String, Option<i32>) {
    let dir = scratch(name);
    let manifest =
        format!("[system]\nio = \"eio.cfg\"\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"main.mod\"]\n{UNITS}");
    fs::write(dir.join("rapid.toml"), manifest).expect("manifest");
    let eio = "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"doStart\" -SignalType \"DO\"\n\n      \
               -Name \"diStop\" -SignalType \"DI\"\n";
    fs::write(dir.join("eio.cfg"), eio).expect("EIO");
    fs::write(dir.join("stop.stim"), "when doStart = 1 after 0.5 s set diStop 1\n").expect("stimulus");
    fs::write(dir.join("main.mod"), module).expect("module");
    let stim = dir.join("stop.stim");
    let out = rapid(&["run", "--quiet", "--stimulus", stim.to_str().unwrap(), dir.to_str().unwrap()]);
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (text(&out.stdout), text(&out.stderr), out.status.code())
}

/// The track's 1000 mm MoveExtJ, stopped 0.5 s in by a trap running `trap`.
fn stopped_track(trap: &str) -> String {
    format!(
        "MODULE main\n  VAR intnum stopint;\n  VAR clock c;\n  VAR jointtarget jt;\n  VAR jointtarget aside;\n  \
         PROC main()\n    CONNECT stopint WITH on_stop;\n    ISignalDI diStop, 1, stopint;\n    ClkStart c;\n    \
         SetDO doStart, 1;\n    MoveExtJ [[0,0,0,0,0,0],[1000,9E9,9E9,9E9,9E9,9E9]], v1000, fine;\n    \
         jt := CJointT();\n    TPWrite \"end \" \\Num:=jt.extax.eax_a;\n  ENDPROC\n  TRAP on_stop\n{trap}  ENDTRAP\nENDMODULE\n"
    )
}

#[test]
fn level_2_moves_start_where_the_external_axes_stopped() {
    // Stopped 0.5 s in, the track is at 75 + 0.35 · 1000 = 425 mm. On path level 2 it
    // goes 100 mm on and back (each a triangle of 2·√(100/6666.7) = 0.245 s + 0.05 s
    // settle): 100 mm from where it stopped, not from the base path's end at 1000 mm.
    // Back where it stopped, RestoPath and StartMove let the base path finish.
    let trap = "    StopMove;\n    StorePath;\n    jt := CJointT();\n    TPWrite \"stopped at \" \\Num:=jt.extax.eax_a;\n    \
                aside := jt;\n    aside.extax.eax_a := jt.extax.eax_a + 100;\n    MoveExtJ aside, v1000, fine;\n    \
                TPWrite \"aside after \" + NumToStr(ClkRead(c), 2);\n    MoveExtJ jt, v1000, fine;\n    RestoPath;\n    \
                StartMove;\n";
    let (stdout, stderr, code) = run_stopped("level_2", &stopped_track(trap));
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stdout, "stopped at 425\naside after 0.79\nend 1000\n");
}

#[test]
fn resto_path_refuses_external_axes_left_elsewhere_on_level_2() {
    let trap = "    StopMove;\n    StorePath;\n    jt := CJointT();\n    aside := jt;\n    \
                aside.extax.eax_a := jt.extax.eax_a + 100;\n    MoveExtJ aside, v1000, fine;\n    RestoPath;\n    StartMove;\n";
    let (_, stderr, code) = run_stopped("level_2_left", &stopped_track(trap));
    assert_eq!(code, Some(1));
    assert!(stderr.contains("RestoPath: the external axes moved on path level 2"), "{stderr}");
}

#[test]
fn the_path_recorder_takes_the_external_axes_back_and_forth() {
    // The track's 500 mm at v1000 takes 500/1000 + 0.15 s ramp + 0.05 s settle = 0.70 s.
    // PathRecMoveBwd takes it back to 0 along the recorded move, the same 0.70 s, and
    // PathRecMoveFwd to 500 again: 1.40 and 2.10 s.
    let body = "    PathRecStart start_id;\n    MoveExtJ [[0,0,0,0,0,0],[500,9E9,9E9,9E9,9E9,9E9]], v1000, fine;\n    \
                StorePath;\n    PathRecMoveBwd;\n    jt := CJointT();\n    \
                TPWrite \"back \" + NumToStr(ClkRead(c), 2) + \" \" \\Num:=jt.extax.eax_a;\n    PathRecMoveFwd;\n    \
                jt := CJointT();\n    TPWrite \"forward \" + NumToStr(ClkRead(c), 2) + \" \" \\Num:=jt.extax.eax_a;\n    \
                RestoPath;\n";
    let (stdout, stderr, code) = run(&project("recorder", "  VAR pathrecid start_id;\n", body, ""));
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stdout, "back 1.40 0\nforward 2.10 500\n");
}

#[test]
fn the_path_recorder_keeps_the_world_path_on_a_track() {
    // As in `a_track_carries_the_robot_and_the_tcp_keeps_its_world_path`: the TCP crosses
    // 100 mm along the world y axis at v100 while the track carries the base 100 mm along
    // x, √2 · 100 mm at √2 · 100 mm/s relative to the base. The track's ramp is the
    // longer one (100 mm/s of its 1000 in 0.015 s; the path's 141 mm/s at 10 m/s² takes
    // 0.0141 s): 1 + 0.015 s + 0.05 s settle = 1.065 s. Back along the recorded path the
    // track returns to 100 mm and the TCP to (300, 0, 400) in the same time. Forward
    // again with \Speed:=v50, the TCP keeps 50 mm/s in the world: √2 · 100 mm at
    // √2 · 50 mm/s relative to the base, 2 + 0.0075 s ramp + 0.05 s settle = 2.06 s,
    // ending at (300, 100, 400), track 200.
    let dir = scratch("recorder_track");
    write_manifest(&dir, TRACK);
    let module = "MODULE main
  CONST robtarget home := [[300,0,400],[0,0,1,0],[0,0,0,0],[0,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget stay := [[300,0,400],[0,0,1,0],[0,0,0,0],[100,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget side := [[300,100,400],[0,0,1,0],[0,0,0,0],[200,9E9,9E9,9E9,9E9,9E9]];
  VAR clock c;
  VAR pathrecid start_id;
  VAR jointtarget jt;
  PROC main()
    ConfL \\Off;
    MoveJ home, v1000, fine, tool0;
    MoveL stay, v1000, fine, tool0;
    PathRecStart start_id;
    MoveL side, v100, fine, tool0;
    StorePath;
    ClkStart c;
    PathRecMoveBwd;
    show \"back\", 3;
    ClkStop c;
    ClkReset c;
    ClkStart c;
    PathRecMoveFwd \\Speed:=v50;
    show \"forward\", 2;
    RestoPath;
  ENDPROC
  PROC show(string what, num decimals)
    jt := CJointT();
    TPWrite what + \" \" + NumToStr(ClkRead(c), decimals) + \" \" + ValToStr(CPos(\\Tool:=tool0)) + \" \" \\Num:=jt.extax.eax_a;
  ENDPROC
ENDMODULE
";
    fs::write(dir.join("main.mod"), module).expect("module");
    let (stdout, stderr, code) = run(&dir);
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stdout, "back 1.065 [300,0,400] 100\nforward 2.06 [300,100,400] 200\n");
}

#[test]
fn the_path_recorder_refuses_a_path_made_in_a_moving_work_object() {
    // A move made while the robot followed the turntable's work object cannot be
    // replayed relative to the robot's base: execution stops, naming why.
    let manifest_units = units_with_table("");
    let dir = scratch("recorder_moving");
    write_manifest(&dir, &manifest_units);
    let module = "MODULE main
  PERS wobjdata wobj_stn1 := [FALSE, FALSE, \"STN1\", [[0,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];
  CONST robtarget home := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,0,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[-100,0,250],[0,0,1,0],[0,0,0,0],[9E9,20,9E9,9E9,9E9,9E9]];
  VAR pathrecid start_id;
  PROC main()
    ConfL \\Off;
    MoveJ home, v1000, fine, tool0;
    PathRecStart start_id;
    MoveL p1, v100, fine, tool0 \\WObj:=wobj_stn1;
    StorePath;
    PathRecMoveBwd;
  ENDPROC
ENDMODULE
";
    fs::write(dir.join("main.mod"), module).expect("module");
    let (_, stderr, code) = run(&dir);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("PathRecMoveBwd: the recorded path was made in a moving work object"), "{stderr}");
}
