//! The layouts public RobotWare systems come in (docs/real-systems.md, "Layouts"): a
//! system whose tasks get their modules from HOME through SYS.cfg's `CAB_TASK_MODULES`
//! (no task folders at all), a configuration folder with HOME beside it, a single task
//! folder straight in `RAPID`, task folders without SYS.cfg, and task folders no
//! configured task uses. Expected results follow RobotWare's rules for
//! `CAB_TASK_MODULES` (`-AllTask`: every task; `-Task`: the task it names, each time it
//! names one; `-Shared`: one module every task sees) and for `CAB_TASKS` (`-Entry`,
//! `main` when not written).

use std::fs;
use std::path::{Path, PathBuf};

use crate::fixture::{copy_dir, rapid_in, repo_root, scratch_in, text, write_files, Scratch};

fn scratch(name: &str) -> Scratch {
    scratch_in("layouts", name)
}

fn fixture(path: &str) -> PathBuf {
    repo_root().join("tests").join(path)
}

/// The `-->` locations of the diagnostics of a human report, in order.
fn locations(stdout: &str) -> Vec<&str> {
    stdout.lines().filter_map(|l| l.trim_start().strip_prefix("--> ")).collect()
}

#[test]
fn a_system_without_task_folders_takes_its_tasks_modules_from_home() {
    // home_only: SYSPAR and HOME, no RAPID. T_ROB1 gets cell.mod, T_LOG log.mod and
    // T_AUX aux.mod (each `-Task`), T_LOG and T_AUX both get common.mod (`-Task` given
    // twice), every task gets user.sys (`-AllTask`); HOME's unused.mod, which no
    // instance names and which calls an undefined routine, belongs to no task.
    let dir = scratch("home_only");
    copy_dir(&fixture("check/backups/home_only"), &dir.join("cell"));
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    let stdout = text(&out.stdout);
    // Two warnings and nothing else: the drive module's DRV1BRAKE read by a
    // cross-connection (EIO.cfg line 11, its value at column 50), and a stray word in
    // PROC.cfg, a domain we do not interpret (line 5, column 36). MMC.cfg's palette
    // sections (`MMC_PAL_1 = MMC_PALETTE:`) are read without a finding.
    assert_eq!(locations(&stdout), ["cell/SYSPAR/EIO.cfg:11:50", "cell/SYSPAR/PROC.cfg:5:36"], "{stdout}");
    assert_eq!(stdout.matches("warning[W0702]").count(), 2, "{stdout}");
    assert!(stdout.ends_with("found 0 errors and 2 warnings in 9 files\n"), "{stdout}");
    assert!(text(&out.stderr).contains("`cell` has no task folders (RAPID/TASKn)"), "{}", text(&out.stderr));

    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    // T_ROB1 starts in its -Entry cell_main, T_LOG in log_main, T_AUX in main (no
    // -Entry); common is in T_LOG and T_AUX but not T_ROB1, cell in T_ROB1 only.
    assert_eq!(
        lines,
        [
            "[T_AUX] main, cell loaded: FALSE",
            "[T_LOG] log_main, common loaded: TRUE",
            "[T_ROB1] cell_main, common loaded: FALSE",
        ]
    );
}

#[test]
fn a_configuration_folder_finds_home_beside_it() {
    // robot/config holds SYS.cfg and EIO.cfg at its root; robot/HOME the modules, as
    // programs that install themselves on a controller ship them. HOME: is robot/HOME.
    let dir = scratch("config_folder");
    copy_dir(&fixture("systems/config_folder"), &dir);
    let out = rapid_in(&dir, &["check", "robot/config"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    // shared_state.sys (-Shared), prog.mod (T_ROB1), watch.mod (watcher), two .cfg.
    assert_eq!(text(&out.stdout), "checked 5 files: no problems found\n");

    let out = rapid_in(&dir, &["run", "robot/config"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // watcher waits for T_ROB1's doProgDone: the order is the program's.
    assert_eq!(text(&out.stdout), "hello from T_ROB1\nhello from watcher\n");
    let log = fs::read_to_string(dir.join("robot/HOME/prog.log")).expect("HOME:prog.log");
    // Write ends its line unless told \NoNewLine.
    assert_eq!(log, "hello from T_ROB1\n");

    // Their parent is no system: the error names the one in it.
    let out = rapid_in(&dir, &["check", "robot"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("these folders in it are systems (name one): `robot/config`"), "{stderr}");
}

const SYS_T_ROB1: &str = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n";

#[test]
fn a_backup_without_its_task_folder_runs_what_sys_cfg_gives_the_task() {
    // An empty RAPID folder (a repository that kept only SYSPAR and HOME); backinfo.txt
    // still lists the two modules TASK1 had. SYS.cfg loads HOME:/prog/main.mod into
    // T_ROB1 and HOME:/user.sys into every task.
    let dir = scratch("missing_task_folder");
    let sys = format!(
        "{SYS_T_ROB1}#\nCAB_TASK_MODULES:\n\n      -File \"HOME:/user.sys\" -ModName \"user\" -AllTask\n\n      \
         -File \"HOME:/prog/main.mod\" -Task \"T_ROB1\"\n"
    );
    let backinfo = ">>TASK1: (T_ROB1,Prog,)\nSYSMOD/user.sys @ \nPROGMOD/Main.mod @ \n\n>>EOF:\n";
    write_files(
        &dir,
        &[
            ("cell/SYSPAR/SYS.cfg", &sys),
            ("cell/BACKINFO/backinfo.txt", backinfo),
            ("cell/HOME/user.sys", "MODULE user(SYSMODULE)\n  CONST num answer := 42;\nENDMODULE\n"),
            (
                "cell/HOME/prog/main.mod",
                "MODULE Main\n  PROC main()\n    TPWrite \"answer \" \\Num:=answer;\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    fs::create_dir_all(dir.join("cell/RAPID")).expect("RAPID");
    for command in ["check", "run"] {
        let out = rapid_in(&dir, &[command, "cell"]);
        assert_eq!(out.status.code(), Some(0), "{command}: {}{}", text(&out.stdout), text(&out.stderr));
        let stderr = text(&out.stderr);
        assert!(
            stderr.contains("backinfo.txt lists 2 module(s) of that folder, which the backup does not hold"),
            "{command}: {stderr}"
        );
    }
    assert_eq!(text(&rapid_in(&dir, &["run", "cell"]).stdout), "answer 42\n");
}

#[test]
fn a_configured_task_without_a_program_is_a_finding_at_its_cab_tasks_line() {
    // SYS.cfg (T_ROB1 at line 5, T_AUX at 7) loads HOME:/main.mod into T_ROB1 only; the
    // backup has no task folders. T_AUX has neither a folder nor a module of HOME: run
    // could not start it, so check and run both report it at line 7 (exit 1), as a
    // finding, not a tool failure.
    let dir = scratch("task_without_program");
    let sys = format!(
        "{SYS_T_ROB1}\n      -Name \"T_AUX\" -Type \"NORMAL\"\n#\nCAB_TASK_MODULES:\n\n      \
         -File \"HOME:/main.mod\" -Task \"T_ROB1\"\n"
    );
    let main = "MODULE Main\n  PROC main()\n    TPWrite \"main\";\n  ENDPROC\nENDMODULE\n";
    write_files(&dir, &[("cell/SYSPAR/SYS.cfg", &sys), ("cell/HOME/main.mod", main)]);
    let finding = "task T_AUX has no program: it has no task folder `cell/RAPID/TASK2`, and SYS.cfg loads no module \
                   of HOME into it (CAB_TASK_MODULES)";
    let check = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(check.status.code(), Some(1), "{}", text(&check.stderr));
    let stdout = text(&check.stdout);
    assert_eq!(locations(&stdout), ["cell/SYSPAR/SYS.cfg:7:1"], "{stdout}");
    assert!(stdout.contains(finding), "{stdout}");
    let run = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(run.status.code(), Some(1), "{}", text(&run.stderr));
    assert_eq!(text(&run.stdout), "");
    assert_eq!(locations(&text(&run.stderr)), ["cell/SYSPAR/SYS.cfg:7:1"], "{}", text(&run.stderr));
    assert!(text(&run.stderr).contains(finding), "{}", text(&run.stderr));

    // The first task the same: its task folder is there but empty (RAPID/TASK1/PROGMOD
    // holds no module), and T_AUX now gets main.mod. At line 5, for check and run.
    let sys = sys.replace("-Task \"T_ROB1\"", "-Task \"T_AUX\"");
    write_files(&dir, &[("cell/SYSPAR/SYS.cfg", &sys), ("cell/RAPID/TASK1/PROGMOD/notes.txt", "none\n")]);
    let finding = "task T_ROB1 has no program: its task folder `cell/RAPID/TASK1` holds no modules in PROGMOD or \
                   SYSMOD, and SYS.cfg loads no module of HOME into it (CAB_TASK_MODULES)";
    for command in ["check", "run"] {
        let out = rapid_in(&dir, &[command, "cell"]);
        assert_eq!(out.status.code(), Some(1), "{command}: {}", text(&out.stderr));
        let report = if command == "run" { text(&out.stderr) } else { text(&out.stdout) };
        assert_eq!(locations(&report), ["cell/SYSPAR/SYS.cfg:5:1"], "{command}: {report}");
        assert!(report.contains(finding), "{command}: {report}");
    }
}

#[test]
fn a_rapid_folder_with_progmod_is_the_one_task() {
    // RAPID/PROGMOD straight, no TASKn and no SYSPAR: task T_ROB1, its modules SYSMOD's
    // then PROGMOD's.
    let dir = scratch("rapid_progmod");
    write_files(
        &dir,
        &[
            ("welder/RAPID/PROGMOD/Main.mod", "MODULE Main\n  PROC main()\n    greet;\n  ENDPROC\nENDMODULE\n"),
            (
                "welder/RAPID/PROGMOD/Lib.mod",
                "MODULE Lib\n  PROC greet()\n    TPWrite GetTaskName();\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let out = rapid_in(&dir, &["check", "welder"]);
    assert_eq!(text(&out.stdout), "checked 2 files: no problems found\n");
    let out = rapid_in(&dir, &["run", "welder"]);
    assert_eq!((out.status.code(), text(&out.stdout)), (Some(0), "T_ROB1\n".to_owned()), "{}", text(&out.stderr));
}

const MAIN_SAYS: &str = "MODULE M\n  PROC main()\n    TPWrite \"task 1\";\n  ENDPROC\nENDMODULE\n";

#[test]
fn without_sys_cfg_every_task_folder_is_checked() {
    // backinfo.txt names TASK1 T_ROB1 and TASK2 T_WATCH; TASK3 it does not name. Each is
    // checked as a task of its own (TASK2's error is T_WATCH's, TASK3's is TASK3's);
    // `rapid run` runs T_ROB1 alone, as it always has without SYS.cfg.
    let dir = scratch("no_syspar");
    let watch = "MODULE W\n  PROC main()\n    no_such_routine;\n  ENDPROC\nENDMODULE\n";
    let third = "MODULE X\n  PROC main()\n    TPWrite undefined_data;\n  ENDPROC\nENDMODULE\n";
    write_files(
        &dir,
        &[
            ("cell/BACKINFO/backinfo.txt", ">>TASK1: (T_ROB1,,)\n\n>>TASK2: (T_WATCH,,)\n\n>>EOF:\n"),
            ("cell/RAPID/TASK1/PROGMOD/M.mod", MAIN_SAYS),
            ("cell/RAPID/TASK2/PROGMOD/W.mod", watch),
            ("cell/RAPID/TASK3/PROGMOD/X.mod", third),
        ],
    );
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = text(&out.stdout);
    assert_eq!(
        locations(&stdout),
        ["cell/RAPID/TASK2/PROGMOD/W.mod:3:5", "cell/RAPID/TASK3/PROGMOD/X.mod:3:13"],
        "{stdout}"
    );
    assert!(stdout.contains("note: in task T_WATCH") && stdout.contains("note: in task TASK3"), "{stdout}");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("backinfo.txt names no task for `cell/RAPID/TASK3`"), "{stderr}");
    assert!(stderr.contains("no SYS.cfg configures the tasks of `cell` (T_ROB1, T_WATCH, TASK3)"), "{stderr}");

    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!((out.status.code(), text(&out.stdout)), (Some(0), "task 1\n".to_owned()), "{}", text(&out.stderr));
}

#[test]
fn a_task_folder_sys_cfg_does_not_configure_is_named_in_a_note() {
    // backinfo.txt puts a task SYS.cfg lacks in TASK2 (a safety option's task, which
    // RobotWare configures itself): not checked, not run, and said so.
    let dir = scratch("unconfigured_folder");
    let broken = "MODULE P\n  PROC main()\n    not_here;\n  ENDPROC\nENDMODULE\n";
    // SYS.cfg also loads a module of RobotWare's own, which no backup holds (line 9:
    // CAB_TASKS takes five lines, then `#`, the type line and a blank).
    let sys = format!(
        "{SYS_T_ROB1}#\nCAB_TASK_MODULES:\n\n      -File \"RELEASE:/options/gui/Screens.sys\" -ModName \"Screens\" -AllTask\n"
    );
    write_files(
        &dir,
        &[
            ("cell/SYSPAR/SYS.cfg", &sys),
            ("cell/BACKINFO/backinfo.txt", ">>TASK1: (T_ROB1,,)\n\n>>TASK2: (PSC_TASK,,)\n\n>>EOF:\n"),
            ("cell/RAPID/TASK1/PROGMOD/M.mod", MAIN_SAYS),
            ("cell/RAPID/TASK2/SYSMOD/P.sys", broken),
        ],
    );
    for command in ["check", "run"] {
        let out = rapid_in(&dir, &[command, "cell"]);
        assert_eq!(out.status.code(), Some(0), "{command}: {}", text(&out.stdout));
        let stderr = text(&out.stderr);
        let note = "`cell/RAPID/TASK2` holds task PSC_TASK (backinfo.txt), which SYS.cfg does not configure";
        assert!(stderr.contains(note), "{command}: {stderr}");
        let note = "SYS.cfg (line 9) loads `RELEASE:/options/gui/Screens.sys`, which is outside HOME";
        assert!(stderr.contains(note), "{command}: {stderr}");
    }
}

/// A configuration folder named with a trailing separator finds the same HOME beside
/// it (its parent is taken from the path's components, not its text).
#[test]
fn a_system_path_may_end_in_a_separator() {
    let dir = scratch("trailing");
    copy_dir(&fixture("systems/config_folder"), &dir);
    let path = Path::new("robot").join("config").display().to_string() + "/";
    let out = rapid_in(&dir, &["check", &path]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
}

#[test]
fn a_system_output_for_a_task_or_robot_the_system_lacks_is_a_check_finding() {
    // `rapid run` refuses to start a system whose SYSSIG_OUT names a task (-Arg2) or a
    // robot (-Arg1) it does not have; `rapid check` finds the same, at the output's
    // line (11 and 13), and the run shows those findings.
    let dir = scratch("system_output_targets");
    let eio = "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"doExec\" -SignalType \"DO\"\n\n      \
               -Name \"doStill\" -SignalType \"DO\"\n#\nSYSSIG_OUT:\n\n      \
               -Status \"TaskExecuting\" -Signal \"doExec\" -Arg2 \"T_NOPE\"\n\n      \
               -Status \"MechUnitNotMoving\" -Signal \"doStill\" -Arg1 \"ROB_2\"\n";
    let files = [
        ("cell/SYSPAR/SYS.cfg", SYS_T_ROB1),
        ("cell/SYSPAR/EIO.cfg", eio),
        ("cell/RAPID/TASK1/PROGMOD/M.mod", MAIN_SAYS),
    ];
    write_files(&dir, &files);
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = text(&out.stdout);
    assert_eq!(locations(&stdout), ["cell/SYSPAR/EIO.cfg:11:1", "cell/SYSPAR/EIO.cfg:13:1"], "{stdout}");
    assert!(stdout.contains("system output `doExec` names task `T_NOPE`, which the system does not have"));
    assert!(stdout.contains("system output `doStill` names mechanical unit `ROB_2`, which the system does not have"));
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!((out.status.code(), text(&out.stdout)), (Some(1), String::new()));
    assert_eq!(locations(&text(&out.stderr)), ["cell/SYSPAR/EIO.cfg:11:1", "cell/SYSPAR/EIO.cfg:13:1"]);
    // The task it names, on the one robot the system has: clean, and it runs.
    let fixed = eio.replace("T_NOPE", "T_ROB1").replace("ROB_2", "ROB_1");
    write_files(&dir, &[("cell/SYSPAR/EIO.cfg", &fixed)]);
    assert_eq!(text(&rapid_in(&dir, &["check", "cell"]).stdout), "checked 3 files: no problems found\n");
    assert_eq!(text(&rapid_in(&dir, &["run", "cell"]).stdout), "task 1\n");
}

#[test]
fn a_manifests_system_output_for_a_task_it_lacks_is_found_in_its_io_file() {
    // The manifest is the first configuration file, its `io` the second: the finding
    // is in the I/O file, at the output's line (9), for check and run alike.
    let dir = scratch("manifest_output");
    let manifest =
        "[system]\nio = \"eio.cfg\"\n\n[[task]]\nname = \"T_ROB1\"\ntype = \"NORMAL\"\nmodules = [\"M.mod\"]\n\
                    motion = true\n";
    let eio =
        "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"doExec\" -SignalType \"DO\"\n#\nSYSSIG_OUT:\n\n      \
               -Status \"TaskExecuting\" -Signal \"doExec\" -Arg2 \"T_OTHER\"\n";
    write_files(&dir, &[("p/rapid.toml", manifest), ("p/eio.cfg", eio), ("p/M.mod", MAIN_SAYS)]);
    let out = rapid_in(&dir, &["check", "p"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert_eq!(locations(&text(&out.stdout)), ["p/eio.cfg:9:1"], "{}", text(&out.stdout));
    let out = rapid_in(&dir, &["run", "p"]);
    assert_eq!((out.status.code(), text(&out.stdout)), (Some(1), String::new()));
    assert!(text(&out.stderr).contains("names task `T_OTHER`, which the system does not have"));
}
