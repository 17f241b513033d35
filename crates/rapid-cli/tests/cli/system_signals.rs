//! System inputs and outputs (EIO.cfg `SYSSIG_IN`, `SYSSIG_OUT`): a stimulus stops
//! and starts the program through them, the controller shows its state on them.
//! Expected outputs are worked out by hand from the manual's rules (§1.11 safe
//! interrupts: at a stop only safe interrupts stay queued, events while stopped are
//! dropped unless safe, queued safe ones run as soon as the program starts again)
//! and from the motion timing model (a 100 mm MoveL at v100 to a fine point takes
//! 1.06 s, as tests/conformance/motion_moves_time.mod works out).

use std::fs;
use std::path::{Path, PathBuf};

use crate::fixture::{copy_dir, rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("system_signals", name)
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check/backups").join(name)
}

/// The changes of `signal` in an `--io-log` CSV: (time, new value).
fn changes<'a>(log: &'a str, signal: &str) -> Vec<(&'a str, &'a str)> {
    log.lines()
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|f| f.get(1) == Some(&signal))
        .map(|f| (f[0], f[3]))
        .collect()
}

#[test]
fn without_a_stop_both_timer_traps_run() {
    // ITimer 1.5 (\SingleSafe) and 1.8 (\Single) during WaitTime 3.
    let dir = scratch("no_stop");
    let out = rapid_in(&dir, &["run", fixture("syssig_cell").to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "safe trap at 1.5\nplain trap at 1.8\nwaited until 3\n");
}

#[test]
fn a_stop_keeps_the_safe_interrupt_and_drops_the_other() {
    // diStop at 1: the task waits (WaitTime 3 since 0), so it stops at once; STOP event
    // routine. Both timers come due while it stands (1.5 safe: queued; 1.8 plain:
    // dropped). diStart at 2.5: RESTART event routine, then the safe trap first, then
    // the 2 s the wait still had: it ends at 4.5.
    let dir = scratch("stop_start");
    fs::write(dir.join("cell.stim"), "at 1 set diStop 1\nat 2.5 set diStart 1\n").expect("stimulus");
    let cell = fixture("syssig_cell");
    let args = ["run", "--stimulus", "cell.stim", "--io-log", "io.csv", "--event-log", cell.to_str().expect("path")];
    let out = rapid_in(&dir, &args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "STOP event at 1\nRESTART event at 2.5\nsafe trap at 2.5\nwaited until 4.5\n");
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    // CycleOn and TaskExecuting: 1 while the program runs, 0 while it stands and after.
    let running = [("0", "1"), ("1", "0"), ("2.5", "1"), ("4.5", "0")];
    assert_eq!(changes(&log, "doCycleOn"), running, "{log}");
    assert_eq!(changes(&log, "doExecuting"), running, "{log}");
    // Motors are on and the mode is automatic from power on.
    assert_eq!(changes(&log, "doMotorOn"), [("0", "1")]);
    assert_eq!(changes(&log, "doAutoOn"), [("0", "1")]);
    // The event log: started, stopped (10151), started again (10150), stopped at the end.
    let stderr = text(&out.stderr);
    let numbers: Vec<&str> =
        stderr.lines().filter_map(|l| l.strip_prefix("event T_ROB1 ")).filter_map(|l| l.split(' ').next()).collect();
    assert_eq!(numbers, ["10002", "10150", "10151", "10150", "10151"], "{stderr}");
}

#[test]
fn a_sys_cfg_configuring_no_task_runs_the_one_task_with_its_event_routines() {
    // The cell above with a SYS.cfg of event routines only (no CAB_TASKS; without -Task
    // they are T_ROB1's, the task backinfo.txt names): the same run as above. The
    // system run indexed the configuration's first task and panicked.
    let dir = scratch("no_tasks");
    copy_dir(&fixture("syssig_cell"), &dir.join("cell"));
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_EXEC_HOOKS:\n\n      -Routine \"on_stop\" -Shelf \"STOP\"\n\n      \
               -Routine \"on_restart\" -Shelf \"RESTART\"\n";
    fs::write(dir.join("cell/SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    fs::write(dir.join("cell.stim"), "at 1 set diStop 1\nat 2.5 set diStart 1\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "cell.stim", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "STOP event at 1\nRESTART event at 2.5\nsafe trap at 2.5\nwaited until 4.5\n");
}

#[test]
fn a_program_nothing_starts_again_ends_the_run_without_failure() {
    let dir = scratch("stranded");
    fs::write(dir.join("stop.stim"), "at 1 set diStop 1\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "stop.stim", fixture("syssig_cell").to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "STOP event at 1\n");
    assert!(
        text(&out.stderr).contains(
            "the program is stopped at 1.000 s of controller time and nothing in the stimulus starts it again"
        ),
        "{}",
        text(&out.stderr)
    );
}

/// A one-task backup `cell` in `dir`: T_ROB1 of `module`, and an EIO.cfg of `eio`.
fn one_task_cell(dir: &Path, module: &str, eio: &str) -> PathBuf {
    let root = dir.join("cell");
    fs::create_dir_all(root.join("RAPID/TASK1/PROGMOD")).expect("task folder");
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    fs::write(root.join("RAPID/TASK1/PROGMOD/Main.mod"), module).expect("module");
    fs::write(root.join("SYSPAR/EIO.cfg"), eio).expect("EIO.cfg");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n";
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    root
}

const PLC_EIO: &str = "EIO:CFG_1.0:6:0::
#
EIO_SIGNAL:

      -Name \"diStart\" -SignalType \"DI\"

      -Name \"doCycleOn\" -SignalType \"DO\"

      -Name \"doError\" -SignalType \"DO\"
#
SYSSIG_IN:

      -Signal \"diStart\" -Action \"Start\"
#
SYSSIG_OUT:

      -Status \"CycleOn\" -Signal \"doCycleOn\"

      -Status \"Error\" -Signal \"doError\" -Arg2 \"T_ROB1\"
";

#[test]
fn a_stop_instruction_waits_for_the_plc_to_start_the_program_again() {
    let dir = scratch("stop_instruction");
    let module = "MODULE Main
  VAR clock c;
  PROC main()
    ClkStart c;
    TPWrite \"before\";
    Stop;
    TPWrite \"after \" \\Num:=Round(ClkRead(c) \\Dec:=2);
  ENDPROC
ENDMODULE
";
    one_task_cell(&dir, module, PLC_EIO);
    fs::write(dir.join("plc.stim"), "at 2 set diStart 1\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "plc.stim", "--io-log", "io.csv", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "before\nafter 2\n");
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    assert_eq!(changes(&log, "doCycleOn"), [("0", "1"), ("0", "0"), ("2", "1"), ("2", "0")], "{log}");
}

#[test]
fn a_task_stopped_by_an_error_shows_it_on_the_error_output() {
    let dir = scratch("error_output");
    let module = "MODULE Main
  PROC main()
    VAR num zero := 0;
    WaitTime 1;
    TPWrite \"\" \\Num:=1 / zero;
  ENDPROC
ENDMODULE
";
    one_task_cell(&dir, module, PLC_EIO);
    let out = rapid_in(&dir, &["run", "--io-log", "io.csv", "cell"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    assert_eq!(changes(&log, "doError"), [("1", "1")], "{log}");
    assert_eq!(changes(&log, "doCycleOn"), [("0", "1"), ("1", "0")], "{log}");
}

/// A one-task backup without SYS.cfg (its task is that of the folder) whose robot
/// makes a 100 mm MoveL at v100; `doMoving` goes to 1 just before it.
fn moving_cell(dir: &Path) -> PathBuf {
    let root = dir.join("cell");
    let module = "MODULE Move
  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR clock c;
  PROC main()
    MoveJ p0, v1000, fine, tool0;
    ClkStart c;
    SetDO doMoving, 1;
    MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
    TPWrite \"MoveL: \" + NumToStr(ClkRead(c), 2);
  ENDPROC
ENDMODULE
";
    let eio = "EIO:CFG_1.0:6:0::
#
EIO_SIGNAL:

      -Name \"diStart\" -SignalType \"DI\"

      -Name \"diStop\" -SignalType \"DI\"

      -Name \"doMoving\" -SignalType \"DO\"
#
SYSSIG_IN:

      -Signal \"diStart\" -Action \"Start\"

      -Signal \"diStop\" -Action \"Stop\"
";
    fs::create_dir_all(root.join("RAPID/TASK1/PROGMOD")).expect("task folder");
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    fs::write(root.join("RAPID/TASK1/PROGMOD/Move.mod"), module).expect("module");
    fs::write(root.join("SYSPAR/EIO.cfg"), eio).expect("EIO.cfg");
    root
}

/// The cycle time `rapid run` reports on stderr, in seconds.
fn cycle_time(stderr: &str) -> f64 {
    let line = stderr.lines().find(|l| l.starts_with("cycle time")).unwrap_or_else(|| panic!("{stderr}"));
    let value = line.split(": ").nth(1).and_then(|v| v.split(' ').next());
    value.and_then(|v| v.parse().ok()).unwrap_or_else(|| panic!("{line}"))
}

#[test]
fn the_robot_stops_on_its_path_and_goes_on_at_the_start() {
    let dir = scratch("motion");
    moving_cell(&dir);
    let robot = ["--robot", "IRB120-3/0.58"];
    let out = rapid_in(&dir, &["run", robot[0], robot[1], "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "MoveL: 1.06\n");
    let plain = cycle_time(&text(&out.stderr));
    // Stopped 0.5 s into the MoveL for 2 s: the move takes 2 s longer, and so does
    // the cycle.
    let stimulus = "when doMoving = 1 after 0.5 s set diStop 1\nwhen diStop = 1 after 2 s set diStart 1\n";
    fs::write(dir.join("plc.stim"), stimulus).expect("stimulus");
    let out = rapid_in(&dir, &["run", robot[0], robot[1], "--stimulus", "plc.stim", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "MoveL: 3.06\n");
    let stopped = cycle_time(&text(&out.stderr));
    assert!((stopped - plain - 2.0).abs() < 1e-3, "{plain} {stopped}");
}

#[test]
fn bad_system_signal_lines_are_refused_with_file_and_line() {
    let dir = scratch("bad");
    copy_dir(&fixture("syssig_cell"), &dir.join("cell"));
    let eio_path = dir.join("cell/SYSPAR/EIO.cfg");
    let eio = fs::read_to_string(&eio_path).expect("EIO.cfg");
    // An unknown action, and a system input on an output.
    let bad = eio
        .replace("-Action \"Stop\"", "-Action \"Jump\"")
        .replace("-Signal \"diStart\" -Action \"Start\" -Arg1 \"CONT\"", "-Signal \"doMotorOn\" -Action \"Start\"");
    fs::write(&eio_path, bad).expect("EIO.cfg");
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("SYSSIG_IN names `doMotorOn`, a DO signal; it must be a DI signal"), "{stderr}");
    assert!(stderr.contains("EIO.cfg:19:"), "{stderr}");
    assert!(stderr.contains("system input `diStop`: unknown action `Jump`"), "{stderr}");
    assert!(stderr.contains("EIO.cfg:21:"), "{stderr}");
    assert!(stderr.contains("the system has errors; it was not run"), "{stderr}");

    // A TaskExecuting output for a task the system does not have.
    fs::write(&eio_path, eio.replace("-Arg2 \"T_ROB1\"", "-Arg2 \"T_NONE\"")).expect("EIO.cfg");
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("names task `T_NONE`, which the system does not have"), "{}", text(&out.stderr));
}

#[test]
fn standard_signals_not_simulated_are_accepted_with_a_warning() {
    let dir = scratch("not_simulated");
    let module = "MODULE Main
  PROC main()
    WaitTime 2;
    TPWrite \"done\";
  ENDPROC
  PROC rInterrupt()
    TPWrite \"interrupt routine\";
  ENDPROC
ENDMODULE
";
    let eio = "EIO:CFG_1.0:6:0::
#
EIO_SIGNAL:

      -Name \"diResetEstop\" -SignalType \"DI\"

      -Name \"diSysReset\" -SignalType \"DI\"

      -Name \"diInterrupt\" -SignalType \"DI\"

      -Name \"doEmStop\" -SignalType \"DO\"

      -Name \"doSimMode\" -SignalType \"DO\"

      -Name \"aoTcpSpeed\" -SignalType \"AO\"
#
SYSSIG_IN:

      -Signal \"diResetEstop\" -Action \"ResetEstop\"

      -Signal \"diSysReset\" -Action \"SysReset\"

      -Signal \"diInterrupt\" -Action \"Interrupt\" -Arg6 \"rInterrupt\"
#
SYSSIG_OUT:

      -Status \"EmStop\" -Signal \"doEmStop\"

      -Status \"SimMode\" -Signal \"doSimMode\"

      -Status \"TCPSpeed\" -Signal \"aoTcpSpeed\"
";
    one_task_cell(&dir, module, eio);
    // ResetEstop (no emergency stop to reset) and SimMode (0: never in simulated mode)
    // are modelled; SysReset, Interrupt and TCPSpeed are accepted with a warning each.
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    let stdout = text(&out.stdout);
    let warnings: Vec<&str> = stdout.lines().filter(|l| l.starts_with("warning[W0702]")).collect();
    assert_eq!(
        warnings,
        [
            "warning[W0702]: system input `diSysReset`: action `SysReset` is accepted but not simulated (the input does nothing in `rapid run`)",
            "warning[W0702]: system input `diInterrupt`: action `Interrupt` is accepted but not simulated (the input does nothing in `rapid run`)",
            "warning[W0702]: system output `aoTcpSpeed`: status `TCPSpeed` is accepted but not simulated (the controller never sets the output)",
        ],
        "{stdout}"
    );
    assert!(
        stdout.contains("EIO.cfg:21:") && stdout.contains("EIO.cfg:23:") && stdout.contains("EIO.cfg:31:"),
        "{stdout}"
    );
    assert!(stdout.contains("found 0 errors and 3 warnings"), "{stdout}");

    // The inputs do nothing: the program runs on to its end at 2 s. The controller
    // never sets the outputs (EmStop and SimMode stay 0; TCPSpeed is not simulated).
    let stimulus = "at 0.5 set diResetEstop 1\nat 1 set diSysReset 1\nat 1.5 set diInterrupt 1\n";
    fs::write(dir.join("plc.stim"), stimulus).expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "plc.stim", "--io-log", "io.csv", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "done\n");
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    assert_eq!(changes(&log, "doEmStop"), [], "{log}");
    assert_eq!(changes(&log, "doSimMode"), [], "{log}");
    assert_eq!(changes(&log, "aoTcpSpeed"), [], "{log}");
}

#[test]
fn mech_unit_outputs_show_whether_the_robot_moves() {
    let dir = scratch("mech_unit_outputs");
    // A 100 mm MoveL at v100 takes 1.01 s (0.01 s to reach 100 mm/s over 0.5 mm, 99 mm
    // at speed, 0.01 s to stop, as C `run_cycles_exitcycle` works out), and a fine
    // point settles 0.05 s more: 0.5 s after the MoveJ the robot moves, and stands
    // still 1.06 s later. A MoveL \Conc to a fly-by point the program never follows up
    // stops at its end (the fly-by point becomes a stop point, no settling): 0.5 s
    // later it moves for 1.01 s, while the program waits. ROB_1 is always active.
    let module = "MODULE Main
  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveJ p0, v1000, fine, tool0;
    WaitTime 0.5;
    MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
    WaitTime 0.5;
    MoveL \\Conc, p0, v100, z10, tool0;
    WaitTime 3;
  ENDPROC
ENDMODULE
";
    let eio = "EIO:CFG_1.0:6:0::
#
EIO_SIGNAL:

      -Name \"doStill\" -SignalType \"DO\" -Access \"ReadOnly\"

      -Name \"doActive\" -SignalType \"DO\" -Access \"ReadOnly\"
#
SYSSIG_OUT:

      -Status \"MechUnitNotMoving\" -Signal \"doStill\" -Arg1 \"ROB_1\"

      -Status \"MechUnitActive\" -Signal \"doActive\" -Arg1 \"ROB_1\"
";
    one_task_cell(&dir, module, eio);
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    assert!(!text(&out.stdout).contains("W0702"), "{}", text(&out.stdout));
    let out = rapid_in(&dir, &["run", "--quiet", "--io-log", "io.csv", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    assert_eq!(changes(&log, "doActive"), [("0", "1")], "{log}");
    let still = changes(&log, "doStill");
    let values: Vec<&str> = still.iter().map(|c| c.1).collect();
    // Still at power on, moving for the MoveJ, still, moving, still, moving, still.
    assert_eq!(values, ["1", "0", "1", "0", "1", "0", "1"], "{log}");
    let at: Vec<f64> = still.iter().map(|c| c.0.parse().expect("time")).collect();
    let near = |a: f64, b: f64| (a - b).abs() < 1e-3;
    assert!(near(at[3] - at[2], 0.5) && near(at[4] - at[3], 1.06), "{at:?}");
    assert!(near(at[5] - at[4], 0.5) && near(at[6] - at[5], 1.01), "{at:?}");
}

#[test]
fn a_mech_unit_output_names_a_unit_the_system_has() {
    let dir = scratch("mech_unit_missing");
    let module = "MODULE Main\n  PROC main()\n    TPWrite \"ran\";\n  ENDPROC\nENDMODULE\n";
    let eio = |arg: &str| {
        format!(
            "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"doStill\" -SignalType \"DO\"\n#\nSYSSIG_OUT:\n\n      \
             -Status \"MechUnitNotMoving\" -Signal \"doStill\"{arg}\n"
        )
    };
    // Without -Arg1 the output is accepted (it follows every unit: see
    // `a_mech_unit_output_without_a_unit_follows_every_robot`). This was a finding;
    // issue 20 decided otherwise on evidence: RobotWare loads such a line, EIO.cfg
    // files a controller wrote (in public backups) have it.
    one_task_cell(&dir, module, &eio(""));
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    assert_eq!(text(&out.stdout), "checked 3 files: no problems found\n");
    // A robot the system does not have: nothing runs.
    one_task_cell(&dir, module, &eio(" -Arg1 \"ROB_2\""));
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("names mechanical unit `ROB_2`, which the system does not have"), "{stderr}");
}

#[test]
fn a_mech_unit_output_without_a_unit_follows_every_robot() {
    // Two robots (MultiMove): T_ROB1 moves ROB_1 from the start, T_ROB2 moves ROB_2
    // from 0.5 s, each the same 2 s joint move, so their moves overlap and ROB_2's
    // ends last. doStill1 and doStill2 show each robot (-Arg1); doAllStill has no
    // -Arg1: 1 while neither moves, so it falls when ROB_1 starts and rises only when
    // ROB_2, the last, stops.
    // uncertain: RobotWare's meaning of the output without -Arg1 (every unit is ours).
    let dir = scratch("mech_unit_every_robot");
    let root = dir.join("cell");
    let task = |n: u32, wait: &str| {
        format!(
            "MODULE Main\n  PROC main()\n{wait}    MoveAbsJ [[30,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, \
             tool0;\n    TPWrite \"T_ROB{n} done\";\n  ENDPROC\nENDMODULE\n"
        )
    };
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      \
               -Name \"T_ROB1\" -Type \"NORMAL\" -UseMechanicalUnitGroup \"rob1\" -MotionTask\n\n      \
               -Name \"T_ROB2\" -Type \"NORMAL\" -UseMechanicalUnitGroup \"rob2\" -MotionTask\n#\n\
               MECHANICAL_UNIT_GROUP:\n\n      -Name \"rob1\" -Robot \"ROB_1\" -MechanicalUnit_1 \"ROB_1\"\n\n      \
               -Name \"rob2\" -Robot \"ROB_2\" -MechanicalUnit_1 \"ROB_2\"\n";
    let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n\n      \
               -name \"ROB_2\" -use_robot_type \"ROB1_120_0.58_3\" -base_frame_pos_x 2\n";
    let eio = "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"doAllStill\" -SignalType \"DO\"\n\n      \
               -Name \"doStill1\" -SignalType \"DO\"\n\n      -Name \"doStill2\" -SignalType \"DO\"\n#\n\
               SYSSIG_OUT:\n\n      -Status \"MechUnitNotMoving\" -Signal \"doAllStill\"\n\n      \
               -Status \"MechUnitNotMoving\" -Signal \"doStill1\" -Arg1 \"ROB_1\"\n\n      \
               -Status \"MechUnitNotMoving\" -Signal \"doStill2\" -Arg1 \"ROB_2\"\n";
    for (path, content) in [
        ("RAPID/TASK1/PROGMOD/Main.mod", task(1, "")),
        ("RAPID/TASK2/PROGMOD/Main.mod", task(2, "    WaitTime 0.5;\n")),
        ("SYSPAR/SYS.cfg", sys.to_owned()),
        ("SYSPAR/MOC.cfg", moc.to_owned()),
        ("SYSPAR/EIO.cfg", eio.to_owned()),
    ] {
        let path = root.join(path);
        fs::create_dir_all(path.parent().expect("parent")).expect("folder");
        fs::write(path, content).expect("write");
    }
    let check = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(check.status.code(), Some(0), "{}", text(&check.stdout));
    let out = rapid_in(&dir, &["run", "--quiet", "--io-log", "io.csv", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let (one, two, all) = (changes(&log, "doStill1"), changes(&log, "doStill2"), changes(&log, "doAllStill"));
    // Each robot: still at power on, moving, still.
    let values = |c: &[(&str, &str)]| c.iter().map(|c| c.1).collect::<Vec<&str>>().join(" ");
    assert_eq!((values(&one), values(&two)), ("1 0 1".to_owned(), "1 0 1".to_owned()), "{log}");
    let at = |c: &[(&str, &str)], i: usize| c[i].0.parse::<f64>().expect("time");
    // The moves overlap: ROB_2 starts before ROB_1 stops, and stops after it.
    assert!(at(&two, 1) < at(&one, 2) && at(&one, 2) < at(&two, 2), "{log}");
    // Every robot: falls with ROB_1's start, rises with ROB_2's stop, once.
    assert_eq!(all, [("0", "1"), (one[1].0, "0"), (two[2].0, "1")], "{log}");
}

#[test]
fn a_robot_held_by_stop_move_shows_standing_still() {
    let dir = scratch("mech_unit_stop_move");
    // 0.5 s after the MoveJ the robot starts a 100 mm MoveL (\Conc: the program goes on),
    // StopMove holds it 0.3 s later, StartMove lets it go on 0.5 s after that: the output
    // shows it standing still from the stop to the start.
    let module = "MODULE Main
  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveJ p0, v1000, fine, tool0;
    WaitTime 0.5;
    MoveL \\Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
    WaitTime 0.3;
    StopMove;
    WaitTime 0.5;
    StartMove;
    WaitRob \\InPos;
  ENDPROC
ENDMODULE
";
    let eio = "EIO:CFG_1.0:6:0::
#
EIO_SIGNAL:

      -Name \"doStill\" -SignalType \"DO\" -Access \"ReadOnly\"
#
SYSSIG_OUT:

      -Status \"MechUnitNotMoving\" -Signal \"doStill\" -Arg1 \"ROB_1\"
";
    one_task_cell(&dir, module, eio);
    let out = rapid_in(&dir, &["run", "--quiet", "--io-log", "io.csv", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let still = changes(&log, "doStill");
    let values: Vec<&str> = still.iter().map(|c| c.1).collect();
    // Power on, the MoveJ, the MoveL until StopMove, from StartMove to the end.
    assert_eq!(values, ["1", "0", "1", "0", "1", "0", "1"], "{log}");
    let at: Vec<f64> = still.iter().map(|c| c.0.parse().expect("time")).collect();
    let near = |a: f64, b: f64| (a - b).abs() < 1e-3;
    assert!(near(at[3] - at[2], 0.5) && near(at[4] - at[3], 0.3) && near(at[5] - at[4], 0.5), "{at:?}");
}
