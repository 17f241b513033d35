//! `rapid check` of several tasks says which task each finding comes from: a module
//! several tasks load (a library listed in each task of a manifest, a module of HOME
//! every task loads) has each problem reported once, with a note naming the tasks whose
//! check found it, and the JSON output lists them in `tasks`. The summary counts files
//! by path, not once per task that loads them. A check of one task prints no task.
//!
//! Every expected report, lines and columns included, is worked out by hand from the
//! files written here: the library's line 3 assigns `count`, which only T_ROB1's module
//! declares (column 5, 5 characters); line 4 writes `missing`, which no task declares
//! (column 13, 7 characters).

use std::fs;
use std::path::Path;

use crate::fixture::{rapid_in, scratch_in, system, text, TaskDef};

const LIB: &str =
    "MODULE Lib(SYSMODULE)\n  PROC lib_log()\n    count := 1;\n    TPWrite missing;\n  ENDPROC\nENDMODULE\n";
const ROB: &str = "MODULE Rob\n  VAR num count := 0;\n  PROC main()\n    lib_log;\n  ENDPROC\nENDMODULE\n";
const B: &str = "MODULE B\n  PROC main()\n    lib_log;\n  ENDPROC\nENDMODULE\n";

/// The library's error at line 3 (`count`), with its note.
fn count_report(path: &str, note: &str) -> String {
    format!(
        "\
error[E0201]: undefined data `count`
 --> {path}:3:5
  |
3 |     count := 1;
  |     ^^^^^
  |
  = note: {note}

"
    )
}

/// The library's error at line 4 (`missing`), with its note.
fn missing_report(path: &str, note: &str) -> String {
    format!(
        "\
error[E0201]: undefined data `missing`
 --> {path}:4:13
  |
4 |     TPWrite missing;
  |             ^^^^^^^
  |
  = note: {note}

"
    )
}

/// Writes `files` (path relative to `dir`, content) into `dir`.
fn write(dir: &Path, files: &[(&str, &str)]) {
    for (path, content) in files {
        let path = dir.join(path);
        fs::create_dir_all(path.parent().expect("parent")).expect("folder");
        fs::write(path, content).expect("write");
    }
}

/// Adds `modules` (CAB_TASK_MODULES instances) to backup `root`'s SYS.cfg.
fn add_task_modules(root: &Path, modules: &str) {
    let path = root.join("SYSPAR/SYS.cfg");
    let sys = fs::read_to_string(&path).expect("SYS.cfg");
    fs::write(&path, format!("{sys}#\nCAB_TASK_MODULES:\n{modules}")).expect("SYS.cfg");
}

fn two_tasks() -> [TaskDef<'static>; 2] {
    [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: ROB },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: B },
    ]
}

const MANIFEST: &str = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"rob/Rob.mod\", \"lib/Lib.sys\"]\n\n\
                        [[task]]\nname = \"T_B\"\nmodules = [\"b/B.mod\", \"lib/Lib.sys\"]\n";

#[test]
fn a_library_listed_in_two_tasks_of_a_manifest_reports_each_problem_once_naming_its_tasks() {
    let dir = scratch_in("check_tasks", "manifest");
    write(&dir, &[("rapid.toml", MANIFEST), ("rob/Rob.mod", ROB), ("b/B.mod", B), ("lib/Lib.sys", LIB)]);
    let out = rapid_in(&dir, &["check", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    // Four files: the manifest, the two tasks' modules and the library (in both tasks).
    let expected = count_report("lib/Lib.sys", "in task T_B")
        + &missing_report("lib/Lib.sys", "in tasks T_ROB1, T_B")
        + "found 2 errors and 0 warnings in 4 files\n";
    assert_eq!(text(&out.stdout), expected);
}

#[test]
fn json_lists_the_tasks_of_each_diagnostic() {
    let dir = scratch_in("check_tasks", "json");
    write(&dir, &[("rapid.toml", MANIFEST), ("rob/Rob.mod", ROB), ("b/B.mod", B), ("lib/Lib.sys", LIB)]);
    let out = rapid_in(&dir, &["check", "--format", "json", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let expected = r#"[
  {
    "file": "lib/Lib.sys",
    "line": 3,
    "column": 5,
    "end_line": 3,
    "end_column": 10,
    "severity": "error",
    "code": "E0201",
    "message": "undefined data `count`",
    "tasks": [
      "T_B"
    ]
  },
  {
    "file": "lib/Lib.sys",
    "line": 4,
    "column": 13,
    "end_line": 4,
    "end_column": 20,
    "severity": "error",
    "code": "E0201",
    "message": "undefined data `missing`",
    "tasks": [
      "T_ROB1",
      "T_B"
    ]
  }
]
"#;
    assert_eq!(text(&out.stdout), expected);
}

#[test]
fn a_clean_system_counts_a_module_of_two_tasks_as_one_file() {
    let dir = scratch_in("check_tasks", "clean");
    let lib = "MODULE Lib(SYSMODULE)\n  PROC lib_log()\n    TPWrite \"log\";\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("rapid.toml", MANIFEST), ("rob/Rob.mod", ROB), ("b/B.mod", B), ("lib/Lib.sys", lib)]);
    let out = rapid_in(&dir, &["check", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    assert_eq!(text(&out.stdout), "checked 4 files: no problems found\n");
}

#[test]
fn a_module_of_home_every_task_loads_is_reported_once_for_the_tasks() {
    let dir = scratch_in("check_tasks", "home_all_tasks");
    let root = system(&dir, &two_tasks(), "");
    write(&root, &[("HOME/Lib.sys", LIB)]);
    add_task_modules(&root, "\n      -File \"HOME:/Lib.sys\" -AllTask\n");
    let out = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    // SYS.cfg, the two tasks' Main.mod and HOME's module.
    let expected = count_report("sys/HOME/Lib.sys", "in task T_B")
        + &missing_report("sys/HOME/Lib.sys", "in tasks T_ROB1, T_B")
        + "found 2 errors and 0 warnings in 4 files\n";
    assert_eq!(text(&out.stdout), expected);
}

#[test]
fn copies_of_a_module_in_each_task_folder_are_files_of_their_own_tasks() {
    let dir = scratch_in("check_tasks", "copies");
    let root = system(&dir, &two_tasks(), "");
    write(&root, &[("RAPID/TASK1/SYSMOD/Lib.sys", LIB), ("RAPID/TASK2/SYSMOD/Lib.sys", LIB)]);
    let out = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    // T_ROB1's copy has the one error T_ROB1 has (its count is declared), T_B's copy
    // both; each copy is a file.
    let expected = missing_report("sys/RAPID/TASK1/SYSMOD/Lib.sys", "in task T_ROB1")
        + &count_report("sys/RAPID/TASK2/SYSMOD/Lib.sys", "in task T_B")
        + &missing_report("sys/RAPID/TASK2/SYSMOD/Lib.sys", "in task T_B")
        + "found 3 errors and 0 warnings in 5 files\n";
    assert_eq!(text(&out.stdout), expected);
}

#[test]
fn a_configuration_finding_names_the_tasks_it_holds_for_unless_it_holds_for_all() {
    let dir = scratch_in("check_tasks", "config");
    let main = "MODULE Main\n  PROC main()\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: main },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: main },
    ];
    let root = system(&dir, &tasks, "");
    // T_ROB1's folder holds Lib.sys, so only T_B loads it from HOME, where it is missing;
    // Gone.sys is missing for both. SYS.cfg: CAB_TASKS at lines 3-7, `#` at 8,
    // CAB_TASK_MODULES at 9, the two modules at lines 11 and 13 (36 and 37 characters).
    write(&root, &[("RAPID/TASK1/SYSMOD/Lib.sys", "MODULE Lib(SYSMODULE)\nENDMODULE\n")]);
    add_task_modules(&root, "\n      -File \"HOME:/Lib.sys\" -AllTask\n\n      -File \"HOME:/Gone.sys\" -AllTask\n");
    let out = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let expected = "\
error[E0701]: task module `HOME:/Lib.sys` is not in the backup's HOME folder
  --> sys/SYSPAR/SYS.cfg:11:1
   |
11 |       -File \"HOME:/Lib.sys\" -AllTask
   | ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^
   |
   = note: in task T_B

error[E0701]: task module `HOME:/Gone.sys` is not in the backup's HOME folder
  --> sys/SYSPAR/SYS.cfg:13:1
   |
13 |       -File \"HOME:/Gone.sys\" -AllTask
   | ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^

found 2 errors and 0 warnings in 4 files
";
    assert_eq!(text(&out.stdout), expected);
}

#[test]
fn a_check_of_one_task_names_no_task() {
    let dir = scratch_in("check_tasks", "one_task");
    let root = system(&dir, &two_tasks()[..1], "");
    write(&root, &[("RAPID/TASK1/SYSMOD/Lib.sys", LIB)]);
    let out = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let expected = "\
error[E0201]: undefined data `missing`
 --> sys/RAPID/TASK1/SYSMOD/Lib.sys:4:13
  |
4 |     TPWrite missing;
  |             ^^^^^^^

found 1 error and 0 warnings in 3 files
";
    assert_eq!(text(&out.stdout), expected);
    let out = rapid_in(&dir, &["check", "--format", "json", "sys"]);
    assert!(!text(&out.stdout).contains("tasks"), "{}", text(&out.stdout));
}
