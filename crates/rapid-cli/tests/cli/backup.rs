//! Controller backup folders given to `rapid check` and `rapid run`: the T_ROB1 task's
//! modules, the signals of `SYSPAR/EIO.cfg`, and `.cfg` findings with file and line.

use std::fs;
use std::path::{Path, PathBuf};

use crate::fixture::{copy_dir, rapid_in, scratch_in, text, write_files as write, Scratch};

fn scratch(name: &str) -> Scratch {
    scratch_in("backup", name)
}

fn backups() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check/backups")
}

#[test]
fn a_backup_checks_clean_with_its_configured_signals() {
    let out = rapid_in(&backups(), &["check", "palletizer"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    // T_ROB1's three modules (TASK2 by backinfo.txt), the three .cfg files, and the
    // two modules of the other task, T_LOGGER (TASK1).
    assert_eq!(text(&out.stdout), "checked 8 files: no problems found\n");
}

#[test]
fn the_task_folder_comes_from_backinfo_not_its_number() {
    let dir = scratch("backinfo");
    let sys =
        "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_LOGGER\"\n\n      -Name \"T_ROB1\" -Type \"NORMAL\"\n";
    write(
        &dir,
        &[
            (
                "two/BACKINFO/backinfo.txt",
                "#\n>>TASK1: (T_ROB1,,)\nPROGMOD\\Robot.mod @ \n\n>>TASK2: (T_LOGGER,,)\n\n>>EOF:\n",
            ),
            ("two/SYSPAR/SYS.cfg", sys),
            (
                "two/RAPID/TASK1/PROGMOD/Robot.mod",
                "MODULE Robot\n  PROC main()\n    TPWrite \"folder 1 runs \" + GetTaskName();\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "two/RAPID/TASK2/PROGMOD/Logger.mod",
                "MODULE Logger\n  PROC main()\n    TPWrite \"folder 2 runs \" + GetTaskName();\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    // Both tasks run (T_LOGGER, a SEMISTATIC task, runs its main over and over until
    // T_ROB1 has ended): which folder each task's program came from is what matters.
    // SYS.cfg lists T_ROB1 second, but backinfo.txt says its folder is TASK1.
    let out = rapid_in(&dir, &["run", "two"]);
    assert_eq!(
        distinct_lines(&out.stdout),
        ["folder 1 runs T_ROB1", "folder 2 runs T_LOGGER"],
        "{}",
        text(&out.stderr)
    );
    // Without backinfo.txt the folder is the task's place in SYS.cfg.
    fs::remove_dir_all(dir.join("two/BACKINFO")).expect("remove");
    let out = rapid_in(&dir, &["run", "two"]);
    assert_eq!(
        distinct_lines(&out.stdout),
        ["folder 1 runs T_LOGGER", "folder 2 runs T_ROB1"],
        "{}",
        text(&out.stderr)
    );
}

/// The lines of an output, sorted, each once.
fn distinct_lines(bytes: &[u8]) -> Vec<String> {
    let mut lines: Vec<String> = text(bytes).lines().map(str::to_owned).collect();
    lines.sort();
    lines.dedup();
    lines
}

#[test]
fn cfg_findings_have_file_and_line_and_unknown_signals_are_undefined() {
    let dir = scratch("broken");
    copy_dir(&backups().join("palletizer"), &dir.join("b"));
    let eio = dir.join("b/SYSPAR/EIO.cfg");
    let broken = fs::read_to_string(&eio).expect("EIO.cfg").replace("-SignalType \"GO\"", "-SignalType \"GX\"");
    fs::write(&eio, broken.replace("-DeviceMap \"8-15\"", "-DeviceMap \"8-15\" stray")).expect("write");
    let out = rapid_in(&dir, &["check", "b"]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains(
            "error[E0701]: unexpected `stray`: attributes start with `-` and a name\n  --> b/SYSPAR/EIO.cfg:26:"
        ),
        "{stdout}"
    );
    assert!(stdout.contains("error[E0701]: signal `goPlacedCount`: unknown signal type `GX`"), "{stdout}");
    assert!(stdout.contains("--> b/SYSPAR/EIO.cfg:28:41"), "{stdout}");
    // The signal with the bad type is not declared, so its use is an undefined name.
    assert!(stdout.contains("error[E0201]: undefined data `goPlacedCount`"), "{stdout}");
    // Both tasks are checked: T_ROB1 (3 modules), T_LOGGER (2) and the 3 .cfg files.
    assert!(stdout.contains("found 3 errors and 0 warnings in 8 files"), "{stdout}");

    let out = rapid_in(&dir, &["run", "b"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty());
    let stderr = text(&out.stderr);
    assert!(stderr.contains("E0701") && stderr.contains("the system has errors; it was not run"), "{stderr}");
}

#[test]
fn a_backup_runs_unattended_on_a_stimulus_and_logs_its_signals() {
    // The palletizer waits for diPartAtPick (WaitDI); the stimulus readies the pallet
    // at 0 s and brings the part at 2.5 s. Worked by hand from the program: the gripper
    // closes at 2.5 s (the cross-connection raises diVacuumOk with it), opens 0.2 s
    // later, the count goes to 1, the conveyor to 120 and doCycleDone starts a pulse.
    // aoConveyorSpeed (0..500 on a 16-bit converter, 0..65535) reads back in converter
    // steps: 120 is 15728.4 steps, so 15728 × 500 / 65535 = 119.996948….
    let dir = scratch("stimulus");
    write(
        &dir,
        &[(
            "stimulus.txt",
            "# palletizer\nat 0 set diPalletReady 1\nat 0 set giLayerPattern 5\nat 2.5 s set diPartAtPick 1\n",
        )],
    );
    copy_dir(&backups().join("palletizer"), &dir.join("palletizer"));
    let out = rapid_in(&dir, &["run", "--stimulus", "stimulus.txt", "--io-log", "io.csv", "palletizer"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty(), "{}", text(&out.stdout));
    let log = std::fs::read_to_string(dir.join("io.csv")).expect("the I/O log is written");
    let expected = "time,signal,old,new,cause\n\
        0,diPalletReady,0,1,Hardware\n\
        0,giLayerPattern,0,5,Hardware\n\
        2.5,diPartAtPick,0,1,Hardware\n\
        2.5,doGripperClose,0,1,Order\n\
        2.5,diVacuumOk,0,1,Cross\n\
        2.7,doGripperClose,1,0,Order\n\
        2.7,diVacuumOk,1,0,Cross\n\
        2.7,goPlacedCount,0,1,Order\n\
        2.7,aoConveyorSpeed,0,119.996948,Order\n\
        2.7,doCycleDone,0,1,Order\n";
    assert_eq!(log, expected);
}

#[test]
fn a_stimulus_needs_inputs_of_the_configuration() {
    let dir = scratch("bad_stimulus");
    // doCycleDone has the default access: only RAPID writes it (doGripperClose, -Access
    // "All", a remote client may write, and so may a stimulus).
    write(&dir, &[("stimulus.txt", "at 1 set doCycleDone 1\n")]);
    let out =
        rapid_in(&dir, &["run", "--stimulus", "stimulus.txt", &backups().join("palletizer").display().to_string()]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("stimulus.txt:1: `doCycleDone` is an output; a stimulus sets inputs, and outputs"),
        "{stderr}"
    );
}

#[test]
fn running_a_backup_starts_t_rob1_at_its_configured_entry() {
    let dir = scratch("runs");
    write(
        &dir,
        &[
            ("cell/SYSPAR/SYS.cfg", "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\\\n      -Entry \"start_cell\"\n"),
            ("cell/SYSPAR/EIO.cfg", "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"diStart\" -SignalType \"DI\"\n"),
            (
                "cell/RAPID/TASK1/PROGMOD/MainModule.mod",
                "MODULE MainModule\n  PROC main()\n    TPWrite \"wrong entry\";\n  ENDPROC\n  PROC start_cell()\n    TPWrite \"cell started, counter \" \\Num:=counter;\n  ENDPROC\nENDMODULE\n",
            ),
            ("cell/RAPID/TASK1/SYSMOD/user.sys", "MODULE user(SYSMODULE)\n  VAR num counter := 7;\nENDMODULE\n"),
        ],
    );
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "cell started, counter 7\n");
    let out = rapid_in(&dir, &["run", "--entry", "main", "cell"]);
    assert_eq!(text(&out.stdout), "wrong entry\n");
}

#[test]
fn a_backup_without_configuration_uses_its_first_task_folder() {
    let dir = scratch("bare");
    write(
        &dir,
        &[
            (
                "bare/RAPID/TASK2/PROGMOD/Other.mod",
                "MODULE Other\n  PROC main()\n    TPWrite \"task 2\";\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "bare/RAPID/TASK1/PROGMOD/First.mod",
                "MODULE First\n  PROC main()\n    TPWrite \"task 1\";\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let out = rapid_in(&dir, &["run", "bare"]);
    assert_eq!(text(&out.stdout), "task 1\n");
}

#[test]
fn a_task_folder_without_modules_is_a_tool_failure() {
    let dir = scratch("empty");
    write(&dir, &[("empty/RAPID/TASK1/PROGMOD/readme.txt", "nothing here\n")]);
    let out = rapid_in(&dir, &["check", "empty"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("holds no modules in PROGMOD or SYSMOD"), "{stderr}");
}

const CFG_EIO: &str = "EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:

      -Name \"diPart\" -SignalType \"DI\" -Device \"d652\" -DeviceMap \"0\"

      -Name \"doGrip\" -SignalType \"DO\" -Device \"d652\" -DeviceMap \"1\"\\
      -Access \"All\" -Default 1

      -Name \"diVirtual\" -SignalType \"DI\"

      -Name \"doLamp\" -SignalType \"DO\" -Device \"d652\" -DeviceMap \"2\"
";

const CFG_SYS: &str = "SYS:CFG_1.0:6:0::
#
CAB_TASKS:

      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\x20
";

const CFG_PROGRAM: &str = r#"MODULE MainModule
    VAR string s := "";
    VAR num n := 0;
    VAR dnum d := 0;
    VAR bool b := FALSE;
    VAR num idx := 0;

    PROC main()
        ReadCfgData "/EIO/EIO_SIGNAL/DOGRIP", "Device", s;
        TPWrite "device " + s;
        ReadCfgData "/EIO/EIO_SIGNAL/doGrip", "Default", n;
        TPWrite "default " \Num:=n;
        ReadCfgData "/EIO/EIO_SIGNAL/doGrip", "Default", d;
        TPWrite "default as dnum " \Dnum:=d;
        ReadCfgData "/SYS/CAB_TASKS/T_ROB1", "MotionTask", b;
        TPWrite "motion task " \Bool:=b;
        ReadCfgData "/SYS/CAB_TASKS/T_ROB1", "Hidden", b;
        TPWrite "hidden " \Bool:=b;
        WHILE idx <> END_OF_LIST DO
            ReadCfgData "/EIO/EIO_SIGNAL/Device/d652", "Name", s \ListNo:=idx;
            TPWrite "on d652: " + s + ", next " \Num:=idx;
        ENDWHILE
        ReadCfgData "/EIO/EIO_SIGNAL/nosuch", "Device", s;
        ReadCfgData "/EIO/EIO_SIGNAL/doGrip", "Label", s;
        ReadCfgData "/MMC/X/y", "Name", s;
        ReadCfgData "EIO/EIO_SIGNAL/doGrip", "Device", s;
        TPWrite "without the slash: " + s;
        ReadCfgData "/EIO/EIO_SIGNAL/doGrip", "Default", s;
        ReadCfgData "/EIO/EIO_SIGNAL/doGrip", "Device", n;
        idx := 3;
        ReadCfgData "/EIO/EIO_SIGNAL/Device/d652", "Name", s \ListNo:=idx;
        idx := -1;
        ReadCfgData "/EIO/EIO_SIGNAL/Device/d652", "Name", s \ListNo:=idx;
        WriteCfgData "/EIO/EIO_SIGNAL/doGrip", "Default", 0;
        WriteCfgData "/EIO/EIO_SIGNAL/doGrip", "Access", "ReadOnly";
        WriteCfgData "/EIO/EIO_SIGNAL/diVirtual", "Access", "All";
        WriteCfgData "/SYS/CAB_TASKS/T_ROB1", "MotionTask", FALSE;
        WriteCfgData "/EIO/EIO_SIGNAL/doGrip", "Access", 3;
        WriteCfgData "/EIO/EIO_SIGNAL/doGrip", "Access", "a""b";
        WriteCfgData "/EIO/EIO_SIGNAL/doGrip", "Label", "x";
        ReadCfgData "/EIO/EIO_SIGNAL/doGrip", "Default", n;
        TPWrite "default now " \Num:=n;
        ReadCfgData "/SYS/CAB_TASKS/T_ROB1", "MotionTask", b;
        TPWrite "motion task now " \Bool:=b;
        SaveCfgData "HOME:/EIO_saved.cfg", EIO_DOMAIN;
        SaveCfgData "HOME:", \File:="sys_saved.cfg", SYS_DOMAIN;
        SaveCfgData "HOME:/x.cfg", PROC_DOMAIN;
        SaveCfgData "HOME:/nofolder/x.cfg", EIO_DOMAIN;
        SaveCfgData "HOME:", EIO_DOMAIN;
        SaveCfgData "usb9:/x.cfg", EIO_DOMAIN;
        MakeDir "HOME:/all";
        SaveCfgData "HOME:/all", ALL_DOMAINS;
        TPWrite "done";
    ERROR
        IF ERRNO = ERR_CFG_NOTFND THEN
            TPWrite "ERR_CFG_NOTFND";
        ELSEIF ERRNO = ERR_CFG_ILLTYPE THEN
            TPWrite "ERR_CFG_ILLTYPE";
        ELSEIF ERRNO = ERR_CFG_OUTOFBOUNDS THEN
            TPWrite "ERR_CFG_OUTOFBOUNDS";
        ELSEIF ERRNO = ERR_CFG_LIMIT THEN
            TPWrite "ERR_CFG_LIMIT";
        ELSEIF ERRNO = ERR_CFG_ILL_DOMAIN THEN
            TPWrite "ERR_CFG_ILL_DOMAIN";
        ELSEIF ERRNO = ERR_CFG_WRITEFILE THEN
            TPWrite "ERR_CFG_WRITEFILE";
        ELSE
            TPWrite "other error";
        ENDIF
        TRYNEXT;
    ENDPROC
ENDMODULE
"#;

#[test]
fn read_write_and_save_configuration_data() {
    let dir = scratch("cfgdata");
    write(
        &dir,
        &[
            ("cell/SYSPAR/EIO.cfg", CFG_EIO),
            ("cell/SYSPAR/SYS.cfg", CFG_SYS),
            ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", CFG_PROGRAM),
        ],
    );
    let out = rapid_in(&dir, &["run", "--home", "home", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let expected = "\
device d652
default 1
default as dnum 1
motion task TRUE
hidden FALSE
on d652: diPart, next 1
on d652: doGrip, next 2
on d652: doLamp, next -1
ERR_CFG_NOTFND
ERR_CFG_NOTFND
ERR_CFG_NOTFND
without the slash: d652
ERR_CFG_ILLTYPE
ERR_CFG_ILLTYPE
ERR_CFG_OUTOFBOUNDS
ERR_CFG_OUTOFBOUNDS
ERR_CFG_ILLTYPE
ERR_CFG_LIMIT
ERR_CFG_NOTFND
default now 0
motion task now FALSE
ERR_CFG_ILL_DOMAIN
ERR_CFG_WRITEFILE
ERR_CFG_WRITEFILE
ERR_CFG_WRITEFILE
done
";
    assert_eq!(text(&out.stdout), expected);
    // One value changed, one replaced, one attribute added; every other byte as read.
    let saved = fs::read_to_string(dir.join("home/HOME/EIO_saved.cfg")).expect("saved EIO");
    let changed = CFG_EIO
        .replace("-Access \"All\" -Default 1", "-Access \"ReadOnly\" -Default 0")
        .replace("-Name \"diVirtual\" -SignalType \"DI\"", "-Name \"diVirtual\" -SignalType \"DI\" -Access \"All\"");
    assert_eq!(saved, changed);
    let sys = fs::read_to_string(dir.join("home/HOME/sys_saved.cfg")).expect("saved SYS");
    assert_eq!(sys, CFG_SYS.replace(" -MotionTask", ""));
    assert_eq!(fs::read_to_string(dir.join("home/HOME/all/EIO.cfg")).expect("all EIO"), changed);
    assert!(dir.join("home/HOME/all/SYS.cfg").is_file());
    // The backup itself is never written.
    assert_eq!(fs::read_to_string(dir.join("cell/SYSPAR/EIO.cfg")).expect("EIO"), CFG_EIO);
}

#[test]
fn a_backups_signals_run_with_their_defaults_groups_and_cross_connections() {
    // EIO.cfg gives diReady the default 1 and giPattern (8 bits) the default 3;
    // EIO_CROSS drives diVacuum from doGrip (manual §2.10: the input follows the
    // output). Worked by hand: the cross-connection shows the output at once, a pulse
    // of 0.5 s is over 0.6 s later, giPattern + 1 is 4, and goCount (4 bits) refuses
    // 16 with ERR_GO_LIM.
    let dir = scratch("io_cell");
    let eio = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n\
      -Name \"diReady\" -SignalType \"DI\" -Default 1\n\n\
      -Name \"diVacuum\" -SignalType \"DI\"\n\n\
      -Name \"doGrip\" -SignalType \"DO\"\n\n\
      -Name \"doDone\" -SignalType \"DO\"\n\n\
      -Name \"giPattern\" -SignalType \"GI\" -DeviceMap \"8-15\" -Default 3\n\n\
      -Name \"goCount\" -SignalType \"GO\" -DeviceMap \"0-3\"\n\
      #\nEIO_CROSS:\n\n      -Name \"vacuum\" -Res \"diVacuum\" -Act1 \"doGrip\"\n";
    let program = "MODULE MainModule\n  PROC main()\n\
      IF diReady = 1 TPWrite \"ready, pattern \" \\Num:=giPattern + 1;\n\
      TPWrite \"vacuum \" \\Num:=diVacuum;\n\
      Set doGrip;\n\
      TPWrite \"vacuum \" \\Num:=diVacuum;\n\
      PulseDO \\PLength:=0.5, doDone;\n\
      TPWrite \"done \" \\Num:=doDone;\n\
      WaitTime 0.6;\n\
      TPWrite \"done \" \\Num:=doDone;\n\
      SetGO goCount, 15;\n\
      TPWrite \"count \" \\Num:=goCount;\n\
      SetGO goCount, 16;\n\
    ERROR\n      IF ERRNO = ERR_GO_LIM TPWrite \"ERR_GO_LIM\";\n      TRYNEXT;\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("cell/SYSPAR/EIO.cfg", eio), ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program)]);
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "ready, pattern 4\nvacuum 0\nvacuum 1\ndone 1\ndone 0\ncount 15\nERR_GO_LIM\n");
}

#[test]
fn a_stimulus_reacts_to_the_programs_outputs() {
    // A handshake: the program closes the gripper and waits for its sensor; the
    // stimulus answers 0.3 s after every doGrip = 1 and drops the sensor at once on
    // doGrip = 0. Worked by hand: the first wait ends at 0.3 s, the sensor is 0 right
    // after Reset, the second cycle starts at 0.3 s and its wait ends at 0.6 s.
    let dir = scratch("handshake");
    let eio = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n\
      -Name \"doGrip\" -SignalType \"DO\"\n\n\
      -Name \"diGripClosed\" -SignalType \"DI\"\n";
    let program = "MODULE MainModule\n  VAR clock c;\n  PROC main()\n\
      ClkStart c;\n\
      FOR i FROM 1 TO 2 DO\n\
        Set doGrip;\n\
        WaitDI diGripClosed, 1;\n\
        TPWrite \"closed at \" \\Num:=ClkRead(c);\n\
        Reset doGrip;\n\
        TPWrite \"sensor \" \\Num:=diGripClosed;\n\
      ENDFOR\n  ENDPROC\nENDMODULE\n";
    let stimulus = "when doGrip = 1 after 0.3 s set diGripClosed 1\nwhen doGrip = 0 set diGripClosed 0\n";
    write(
        &dir,
        &[
            ("cell/SYSPAR/EIO.cfg", eio),
            ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program),
            ("stimulus.txt", stimulus),
        ],
    );
    let out = rapid_in(&dir, &["run", "--stimulus", "stimulus.txt", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "closed at 0.3\nsensor 0\nclosed at 0.6\nsensor 0\n");
}

#[test]
fn a_backups_home_folder_is_the_home_device() {
    // A backup carries the controller's HOME folder: HOME: files are read from it.
    let dir = scratch("home_device");
    let program = "MODULE MainModule\n  VAR iodev f;\n  PROC main()\n\
      Open \"HOME:/recipe.txt\", f \\Read;\n\
      TPWrite \"recipe \" + ReadStr(f);\n\
      Close f;\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program), ("cell/HOME/recipe.txt", "blue boxes\n")]);
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "recipe blue boxes\n");
}

/// A track as RobotWare's MOC.cfg links it (our own values): 10 m long, the motor's
/// 300 rad/s over a gear ratio of 300 rad/m, so 1 m/s; 2.5 m/s²; it carries ROB_1.
const MOC_TRACK: &str = "MOC:CFG_1.0:6:0::
#
MECHANICAL_UNIT:

      -name \"ROB_1\"

      -name \"TRK1\" -use_single_0 \"TRK1\" -activate_at_start_up  -deactivation_forbidden
#
ROBOT:

      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\" -base_frame_coordinated \"TRK1\"
#
SINGLE:

      -name \"TRK1\" -use_single_type \"TRK1\" -use_joint \"TRK1\"
#
SINGLE_TYPE:

      -name \"TRK1\" -mechanics \"TRACK\"
#
JOINT:

      -name \"TRK1\" -logical_axis 7 -use_arm \"TRK1\" -use_transmission \"TRK1\" -use_drive_system \"TRK1\"
#
ARM:

      -name \"TRK1\" -use_acc_data \"TRK1\" -upper_joint_bound 10 -lower_joint_bound -0.1
#
ACC_DATA:

      -name \"TRK1\" -wc_acc 2.5 -wc_dec 2.5
#
TRANSMISSION:

      -name \"TRK1\" -transm_joint 300
#
DRIVE_SYSTEM:

      -name \"TRK1\" -use_stress_duty_cycle \"TRK1\"
#
STRESS_DUTY_CYCLE:

      -name \"TRK1\" -speed_absolute_max 300
";

#[test]
fn a_track_of_the_backups_moc_cfg_moves_and_carries_the_robot() {
    // The track goes 500 mm at its 1000 mm/s with 2500 mm/s² (v1000's v_leax does not
    // limit it): 500/1000 + 1000/2500 = 0.9 s, + 0.05 s settle. The robot stands on it:
    // its TCP goes 500 mm along the world x axis with it. The unit may not be
    // deactivated (-deactivation_forbidden).
    let dir = scratch("moc_track");
    let program = "MODULE MainModule
  VAR clock c;
  VAR jointtarget jt;
  VAR pos before;
  VAR pos after;
  PROC main()
    MoveAbsJ [[0,0,0,0,90,0],[0,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    before := CPos(\\Tool:=tool0);
    ClkStart c;
    MoveExtJ [[0,0,0,0,90,0],[500,9E9,9E9,9E9,9E9,9E9]], v1000, fine;
    TPWrite \"t \" + NumToStr(ClkRead(c), 2);
    jt := CJointT();
    TPWrite \"track \" \\Num:=jt.extax.eax_a;
    after := CPos(\\Tool:=tool0);
    TPWrite \"moved \" \\Pos:=after - before;
    DeactUnit TRK1;
  ENDPROC
ENDMODULE
";
    write(&dir, &[("cell/SYSPAR/MOC.cfg", MOC_TRACK), ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program)]);
    let out = rapid_in(&dir, &["run", "--quiet", "cell"]);
    assert_eq!(text(&out.stdout), "t 0.95\ntrack 500\nmoved [500,0,0]\n", "{}", text(&out.stderr));
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("TRK1 is configured with deactivation forbidden"), "{stderr}");
    assert!(!stderr.contains("are not read"), "{stderr}");
}

#[test]
fn the_robot_stands_where_the_backups_moc_cfg_puts_its_base() {
    // MOC.cfg puts ROB_1's base 0.5 m up and turned 90° about z: its x axis is the
    // world's y. The world target [0, 300, 900] pointing down (in the base frame; in the
    // world [0, -0.70711, 0.70711, 0]) is [300, 0, 400] in the base frame, which the
    // IRB 120 reaches at [0, 0.5818, 28.9565, 0, 60.4616, 0] (an independent inverse
    // kinematics, tests/hand/). CPos reports the world.
    let dir = scratch("moc_base");
    let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\\\n      \
               -base_frame_pos_z 0.5 -base_frame_orient_u0 0.70710678 -base_frame_orient_u3 0.70710678\n";
    let program = "MODULE MainModule
  VAR jointtarget jt;
  VAR pos w;
  PROC main()
    MoveJ [[0,300,900],[0,-0.70710678,0.70710678,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    jt := CJointT();
    TPWrite \"axes \" + NumToStr(jt.robax.rax_1, 3) + \" \" + NumToStr(jt.robax.rax_2, 3) + \" \" + NumToStr(jt.robax.rax_3, 3)
      + \" \" + NumToStr(jt.robax.rax_5, 3);
    w := CPos(\\Tool:=tool0 \\WObj:=wobj0);
    TPWrite \"world \" \\Pos:=w;
  ENDPROC
ENDMODULE
";
    write(&dir, &[("cell/SYSPAR/MOC.cfg", moc), ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program)]);
    let out = rapid_in(&dir, &["run", "--quiet", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "axes 0.000 0.582 28.957 60.462\nworld [0,300,900]\n");
}

#[test]
fn the_axis_ranges_of_the_backups_moc_cfg_bound_the_robot() {
    // MOC.cfg narrows axis 1 of ROB_1 to ±1.5708 rad = ±90° (the IRB 120 has ±165°):
    // 80° is reached, 100° is out of range (50028 for axis 1).
    let dir = scratch("moc_ranges");
    let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\\\n      \
               -use_joint_0 \"rob1_1\"\n#\nARM:\n\n      -name \"rob1_1\" -upper_joint_bound 1.5708 -lower_joint_bound -1.5708\n";
    let program = "MODULE MainModule
  PROC main()
    MoveAbsJ [[80,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    TPWrite \"at 80\";
    MoveAbsJ [[100,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    TPWrite \"at 100\";
  ENDPROC
ENDMODULE
";
    write(&dir, &[("cell/SYSPAR/MOC.cfg", moc), ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program)]);
    let out = rapid_in(&dir, &["run", "--quiet", "cell"]);
    assert_eq!(text(&out.stdout), "at 80\n");
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("50028 Joint 1 out of range"), "{}", text(&out.stderr));
}

#[test]
fn a_task_without_its_folder_is_reported_not_given_another_tasks_program() {
    // SYS.cfg configures T_ROB1 and T_BG; the backup holds RAPID/TASK1 only. T_BG has no
    // program: the run and the check say so (T_BG ran T_ROB1's modules before), at
    // T_BG's CAB_TASKS line (7). This was a tool failure (exit 2); issue 20 decided
    // that whatever keeps `run` from starting is a finding at its place, in check and
    // run alike (exit 1, the finding shown as the others).
    let dir = scratch("task_without_folder");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n\n      \
               -Name \"T_BG\" -Type \"SEMISTATIC\"\n";
    let module = "MODULE M\n  PROC main()\n    TPWrite \"main runs in \" + GetTaskName();\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("sys/SYSPAR/SYS.cfg", sys), ("sys/RAPID/TASK1/PROGMOD/M.mod", module)]);
    let finding = "error[E0701]: task T_BG has no program: it has no task folder `sys/RAPID/TASK2`, and SYS.cfg loads \
                   no module of HOME into it (CAB_TASK_MODULES)\n --> sys/SYSPAR/SYS.cfg:7:1\n";
    for command in ["run", "check"] {
        let out = rapid_in(&dir, &[command, "sys"]);
        assert_eq!(out.status.code(), Some(1), "{command}: {}", text(&out.stdout));
        let report = if command == "run" { text(&out.stderr) } else { text(&out.stdout) };
        assert!(report.starts_with(finding), "{command}: {report}");
        assert!(report.contains("found 1 error and 0 warnings"), "{command}: {report}");
    }
    let run = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(text(&run.stdout), "");
    assert!(text(&run.stderr).ends_with("the system has errors; it was not run\n"), "{}", text(&run.stderr));
}

#[test]
fn a_task_is_the_modules_backinfo_lists() {
    let dir = scratch("backinfo_modules");
    // backinfo.txt lists MainModule.mod for TASK1; Old.mod, left in the folder, is not
    // part of the task (the controller saved what it had loaded): its error does not
    // count and its procedure is not there.
    let main = "MODULE MainModule\n  PROC main()\n    TPWrite \"main\";\n  ENDPROC\nENDMODULE\n";
    let old = "MODULE Old\n  PROC old()\n    undefined_thing;\n  ENDPROC\nENDMODULE\n";
    let backinfo = "#\n>>SYSPAR:\nSYS.cfg\n\n>>TASK1: (T_ROB1,,)\nPROGMOD\\MainModule.mod @ \n\n>>EOF:\n";
    write(
        &dir,
        &[
            ("cell/BACKINFO/backinfo.txt", backinfo),
            ("cell/SYSPAR/SYS.cfg", CFG_SYS),
            ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", main),
            ("cell/RAPID/TASK1/PROGMOD/Old.mod", old),
        ],
    );
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "main\n");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("note: `cell/RAPID/TASK1/PROGMOD/Old.mod` is not among the modules backinfo.txt lists for task T_ROB1: it is not loaded"), "{stderr}");
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    assert!(!text(&out.stdout).contains("Old.mod"), "{}", text(&out.stdout));
    // A module it lists that the folder lacks: the backup is refused, naming it.
    let listed_twice =
        backinfo.replace("PROGMOD\\MainModule.mod @ \n", "PROGMOD\\MainModule.mod @ \nSYSMOD\\user.sys @ \n");
    write(&dir, &[("cell/BACKINFO/backinfo.txt", &listed_twice)]);
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(text(&out.stdout), "");
    assert!(text(&out.stderr).contains("backinfo.txt lists module `SYSMOD\\user.sys`"), "{}", text(&out.stderr));
}
