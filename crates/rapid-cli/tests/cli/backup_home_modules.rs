//! Modules SYS.cfg loads from HOME (`CAB_TASK_MODULES`): RobotWare loads them into the
//! tasks they name at start-up; a backup keeps them in its HOME folder (one installed
//! with `-Install` is not saved in the task folder).

use std::fs;
use std::path::Path;

use crate::fixture::{rapid_in, scratch_in, system, text, TaskDef};

/// Adds `modules` (CAB_TASK_MODULES instances) to the backup's SYS.cfg.
fn add_task_modules(root: &Path, modules: &str) {
    let path = root.join("SYSPAR/SYS.cfg");
    let sys = fs::read_to_string(&path).expect("SYS.cfg");
    fs::write(&path, format!("{sys}#\nCAB_TASK_MODULES:\n{modules}")).expect("SYS.cfg");
}

const TOOLS: &str = "MODULE tools(SYSMODULE)\n  PROC greet(string who)\n    TPWrite \"hello \" + who;\n  \
                     ENDPROC\nENDMODULE\n";

#[test]
fn a_module_of_home_named_for_a_task_is_loaded_into_that_task_only() {
    let dir = scratch_in("backup_home_modules", "per_task");
    let rob = "MODULE R\n  PROC main()\n    greet \"rob\";\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC main()\n    WaitTime 0.1;\n    TPWrite \"b\";\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: rob },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    let root = system(&dir, &tasks, "");
    fs::create_dir_all(root.join("HOME/Lib")).expect("HOME");
    fs::write(root.join("HOME/Lib/tools.sys"), TOOLS).expect("module");
    add_task_modules(&root, "\n      -File \"HOME:/Lib/tools.sys\" -Task \"T_ROB1\" -Install\n");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "hello rob\nb\n");

    // T_B does not have it: its call of greet is an error of T_B's program.
    let b_calls = "MODULE B\n  PROC main()\n    greet \"b\";\n  ENDPROC\nENDMODULE\n";
    fs::write(root.join("RAPID/TASK2/PROGMOD/Main.mod"), b_calls).expect("module");
    let out = rapid_in(&dir, &["check", "sys"]);
    let all = text(&out.stdout) + &text(&out.stderr);
    assert_eq!(all.matches("no procedure `greet` is defined in this task").count(), 1, "{all}");
    assert!(all.contains("TASK2/PROGMOD/Main.mod:3"), "{all}");
}

#[test]
fn a_module_of_home_for_all_tasks_is_loaded_once_into_each_unless_the_task_folder_has_it() {
    let dir = scratch_in("backup_home_modules", "all_tasks");
    let rob = "MODULE R\n  PROC main()\n    greet \"rob\";\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC main()\n    WaitTime 0.1;\n    greet \"b\";\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: rob },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    let root = system(&dir, &tasks, "");
    fs::create_dir_all(root.join("HOME")).expect("HOME");
    fs::write(root.join("HOME/tools.sys"), TOOLS).expect("module");
    // T_ROB1's folder holds its copy already (loaded, not installed, so saved with the
    // task): it is not loaded a second time (that would declare greet twice).
    fs::create_dir_all(root.join("RAPID/TASK1/SYSMOD")).expect("SYSMOD");
    fs::write(root.join("RAPID/TASK1/SYSMOD/tools.sys"), TOOLS).expect("module");
    add_task_modules(&root, "\n      -File \"HOME:/tools.sys\" -AllTask\n");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "hello rob\nhello b\n");

    // Missing from HOME: SYS.cfg's line says so.
    fs::remove_file(root.join("HOME/tools.sys")).expect("remove");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(err.contains("task module `HOME:/tools.sys` is not in the backup's HOME folder"), "{err}");
    assert!(err.contains("SYS.cfg:"), "{err}");
    // `rapid check` says the same.
    let out = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    let all = text(&out.stdout);
    assert!(all.contains("task module `HOME:/tools.sys` is not in the backup's HOME folder"), "{all}");
}
