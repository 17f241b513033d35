//! World zones on the simulated robot: WZDOSet `\Before` against `\Inside`, seen in the
//! I/O log (`--io-log`) at the times worked out by hand from the timing model.

use std::fs;
use std::path::Path;
use std::process::Output;

use crate::fixture::{rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("zones", name)
}

/// Runs backup `sys` in `dir`: one motion task running `module`, DO signals `outputs`.
fn run(dir: &Path, module: &str, outputs: &[&str]) -> Output {
    let signals: String = outputs.iter().map(|name| format!("\n      -Name \"{name}\" -SignalType \"DO\"\n")).collect();
    run_with_signals(dir, module, &signals)
}

/// Runs backup `sys` in `dir`: one motion task running `module`, the EIO_SIGNAL lines
/// `signals`.
fn run_with_signals(dir: &Path, module: &str, signals: &str) -> Output {
    let root = dir.join("sys");
    let folder = root.join("RAPID/TASK1/PROGMOD");
    fs::create_dir_all(&folder).expect("task folder");
    fs::write(folder.join("Main.mod"), module).expect("module");
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n";
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    fs::write(root.join("SYSPAR/EIO.cfg"), format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{signals}")).expect("EIO.cfg");
    rapid_in(dir, &["run", "--quiet", "--io-log", "io.csv", "sys"])
}

/// When `signal` first became `new` in an `--io-log` CSV (time,signal,old,new,cause).
fn change_time(log: &str, signal: &str, new: &str) -> f64 {
    log.lines()
        .map(|l| l.split(',').collect::<Vec<_>>())
        .find(|f| f.len() > 3 && f[1] == signal && f[3] == new)
        .and_then(|f| f[0].parse().ok())
        .unwrap_or_else(|| panic!("{signal} never became {new}: {log}"))
}

#[test]
fn wzdoset_before_sets_its_output_a_braking_distance_early() {
    let dir = scratch("before");
    // The slab x = 340..360 mm lies on a 100 mm MoveL from x = 300 at v500. IRB 120:
    // 10 m/s² path acceleration, so the TCP speeds up for 500 / 10000 = 0.05 s over
    // 12.5 mm and is at x = 312.5 + 500 (t - 0.05) while it cruises (until x = 387.5).
    // `\Inside`: in at x = 340, t = 0.05 + 27.5 / 500 = 0.105 s; out past x = 360,
    // t = 0.05 + 47.5 / 500 = 0.145 s.
    // `\Before`: braking at 500 mm/s takes 500² / (2 · 10000) = 12.5 mm, so the output
    // follows x + 12.5: in at x = 327.5, t = 0.05 + 15 / 500 = 0.08 s; out at x = 347.5,
    // t = 0.05 + 35 / 500 = 0.12 s. Both to the 4 ms path resolution.
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR shapedata slab;\n  VAR wztemporary wzIn;\n  VAR wztemporary wzBefore;\n  \
                   PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    \
                   WZBoxDef \\Inside, slab, [340, -50, 350], [360, 50, 450];\n    \
                   WZDOSet \\Temp, wzIn \\Inside, slab, doInside, 1;\n    \
                   WZDOSet \\Temp, wzBefore \\Before, slab, doBefore, 1;\n    SetDO doStart, 1;\n    \
                   MoveL Offs(p0, 100, 0, 0), v500, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let out = run(&dir, program, &["doStart", "doInside", "doBefore"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let start = change_time(&log, "doStart", "1");
    for (signal, value, expected) in
        [("doInside", "1", 0.105), ("doInside", "0", 0.145), ("doBefore", "1", 0.08), ("doBefore", "0", 0.12)]
    {
        let after = change_time(&log, signal, value) - start;
        assert!((after - expected).abs() <= 0.0055, "{signal} = {value} after {after} s, expected {expected}: {log}");
    }
}

#[test]
fn a_zone_on_a_move_to_a_fly_by_point_switches_as_the_robot_passes() {
    let dir = scratch("fly_by");
    // A 300 mm MoveL along y at v100 to a fly-by point (z10), then on. The slab
    // y = -60 … -40 lies on its straight part. The TCP ramps up for 0.01 s over 0.5 mm and
    // then cruises: in at y = -60, t = 0.01 + 89.5 / 100 = 0.905 s; out past y = -40,
    // t = 0.01 + 109.5 / 100 = 1.105 s (to the 4 ms path resolution). The program gives
    // the next move only near the fly-by point, about 2.9 s in; the output must not wait
    // for it (it changed then, in and out at once).
    let program = "MODULE S\n  CONST robtarget p0 := [[300, -150, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR shapedata slab;\n  VAR wztemporary wzIn;\n  \
                   PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    \
                   WZBoxDef \\Inside, slab, [250, -60, 350], [350, -40, 450];\n    \
                   WZDOSet \\Temp, wzIn \\Inside, slab, doInside, 1;\n    SetDO doStart, 1;\n    \
                   MoveL Offs(p0, 0, 300, 0), v100, z10, tool0;\n    \
                   MoveL Offs(p0, 0, 300, -50), v100, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let out = run(&dir, program, &["doStart", "doInside"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let start = change_time(&log, "doStart", "1");
    for (value, expected) in [("1", 0.905), ("0", 1.105)] {
        let after = change_time(&log, "doInside", value) - start;
        assert!((after - expected).abs() <= 0.0055, "doInside = {value} after {after} s, expected {expected}: {log}");
    }
}

#[test]
fn a_read_only_output_follows_its_zone() {
    // The zone supervision sets a WZDOSet output, not the program: an output the
    // program may not write (-Access "ReadOnly", as real cells configure their zone
    // outputs so nothing else writes them) follows the zone all the same. The robot
    // starts inside the box around p0 (the output is 1 at once) and leaves it: 100 mm
    // along x at v500 from x = 300, out past x = 320: 0.05 s ramp over 12.5 mm, then
    // t = 0.05 + 7.5 / 500 = 0.065 s.
    let dir = scratch("read_only");
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR shapedata box;\n  VAR wztemporary wzHome;\n  \
                   PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    \
                   WZBoxDef \\Inside, box, [280, -20, 380], [320, 20, 420];\n    SetDO doStart, 1;\n    \
                   WZDOSet \\Temp, wzHome \\Inside, box, doHome, 1;\n    \
                   MoveL Offs(p0, 100, 0, 0), v500, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let signals = "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"doHome\" -SignalType \"DO\" -Access \"ReadOnly\"\n";
    let out = run_with_signals(&dir, program, signals);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let start = change_time(&log, "doStart", "1");
    assert!((change_time(&log, "doHome", "1") - start).abs() < 1e-9, "{log}");
    let after = change_time(&log, "doHome", "0") - start;
    assert!((after - 0.065).abs() <= 0.0055, "doHome = 0 after {after} s, expected 0.065: {log}");
}
