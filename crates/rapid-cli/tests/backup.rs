//! Controller backup folders given to `rapid check` and `rapid run`: the T_ROB1 task's
//! modules, the signals of `SYSPAR/EIO.cfg`, and `.cfg` findings with file and line.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn backups() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check/backups")
}

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("backup").join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

/// `rapid ARGS…` run in `dir`, so messages hold relative paths.
fn rapid_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rapid")).current_dir(dir).args(args).output().expect("run rapid")
}

fn write(root: &Path, files: &[(&str, &str)]) {
    for (path, text) in files {
        let path = root.join(path);
        fs::create_dir_all(path.parent().expect("parent")).expect("folder");
        fs::write(path, text).expect("write");
    }
}

fn copy_dir(from: &Path, to: &Path) {
    fs::create_dir_all(to).expect("folder");
    for entry in fs::read_dir(from).expect("read folder") {
        let entry = entry.expect("entry");
        let target = to.join(entry.file_name());
        if entry.path().is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            fs::copy(entry.path(), target).expect("copy");
        }
    }
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn a_backup_checks_clean_with_its_configured_signals() {
    let out = rapid_in(&backups(), &["check", "palletizer"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    // T_ROB1's three modules (TASK2 by backinfo.txt) and the three .cfg files.
    assert_eq!(text(&out.stdout), "checked 6 files: no problems found\n");
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
                "MODULE Robot\n  PROC main()\n    TPWrite \"robot\";\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "two/RAPID/TASK2/PROGMOD/Logger.mod",
                "MODULE Logger\n  PROC main()\n    TPWrite \"logger\";\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    // SYS.cfg lists T_ROB1 second, but backinfo.txt says its folder is TASK1.
    let out = rapid_in(&dir, &["run", "two"]);
    assert_eq!(text(&out.stdout), "robot\n", "{}", text(&out.stderr));
    // Without backinfo.txt the folder is the task's place in SYS.cfg.
    fs::remove_dir_all(dir.join("two/BACKINFO")).expect("remove");
    let out = rapid_in(&dir, &["run", "two"]);
    assert_eq!(text(&out.stdout), "logger\n", "{}", text(&out.stderr));
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
    assert!(stdout.contains("found 3 errors and 0 warnings in 6 files"), "{stdout}");

    let out = rapid_in(&dir, &["run", "b"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty());
    let stderr = text(&out.stderr);
    assert!(stderr.contains("E0701") && stderr.contains("the system has errors; it was not run"), "{stderr}");
}

#[test]
fn running_a_backup_that_uses_io_is_refused_at_load() {
    let out = rapid_in(&backups(), &["run", "palletizer"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty());
    let stderr = text(&out.stderr);
    assert!(stderr.contains("the built-in `WaitDI` is not supported by `rapid run` yet"), "{stderr}");
    assert!(stderr.contains("the program was not run"), "{stderr}");
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
