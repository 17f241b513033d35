//! Inputs a user can give that once took quadratic time, generated here (nothing large
//! is committed): a SYS.cfg naming a thousand tasks is refused by its task limit before
//! any task is read, by `rapid check` and `rapid run` alike; and a `.pgf` that lists a
//! `.pgf` is refused with one error instead of being parsed as RAPID.
//!
//! Expected values by hand: 20 tasks at most (RAPID overview §1.20), so with 1000
//! configured, 980 are too many and the 21st task's `-Name` (line 5 + 2 × 20 = 45 of
//! the SYS.cfg written below, column 7) carries the finding.

use std::fs;
use std::path::Path;
use std::time::{Duration, Instant};

use crate::fixture::{rapid_in, scratch_in, stderr, stdout, write_files};

const MAIN: &str = "MODULE Main\n  PROC main()\n  ENDPROC\nENDMODULE\n";

/// A backup whose SYS.cfg names `n` tasks (T_ROB1, T_2, …) and which holds only
/// TASK1's folder.
fn backup_of_tasks(dir: &Path, n: usize) {
    let mut sys = String::from("SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n");
    for i in 1..=n {
        let name = if i == 1 { "T_ROB1".to_owned() } else { format!("T_{i}") };
        sys.push_str(&format!("\n      -Name \"{name}\" -Type \"NORMAL\"\n"));
    }
    write_files(dir, &[("b/SYSPAR/SYS.cfg", &sys), ("b/RAPID/TASK1/PROGMOD/Main.mod", MAIN)]);
}

const LIMIT: &str = "error[E0701]: at most 20 tasks; 980 more are configured\n  --> b/SYSPAR/SYS.cfg:45:7\n";

#[test]
fn a_thousand_tasks_are_refused_by_the_limit_at_once_by_check_and_run() {
    let dir = scratch_in("scale", "thousand_tasks");
    backup_of_tasks(&dir, 1000);
    let started = Instant::now();
    let check = rapid_in(&dir, &["check", "b"]);
    // Before the limit came first, this took minutes (each task re-read the backup,
    // each instance's line was counted from the top of the file); now it reads one
    // task. The bound is generous for a loaded machine and a debug build.
    assert!(started.elapsed() < Duration::from_secs(10), "check took {:?}", started.elapsed());
    let run = rapid_in(&dir, &["run", "b"]);
    assert_eq!(check.status.code(), Some(1));
    assert_eq!(run.status.code(), Some(1));
    assert!(stdout(&check).starts_with(LIMIT), "{}", stdout(&check));
    assert!(stderr(&run).starts_with(LIMIT), "{}", stderr(&run));
    // The one finding: no "T_2 has no task folder" for the tasks never read.
    assert!(stdout(&check).contains("found 1 error and 0 warnings"), "{}", stdout(&check));
}

#[test]
fn a_program_file_listing_a_program_file_is_one_error() {
    let dir = scratch_in("scale", "nested_pgf");
    let listing = |entries: &[&str]| {
        let modules: String = entries.iter().map(|e| format!("    <Module>{e}</Module>\n")).collect();
        format!("<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>\n<Program>\n{modules}</Program>\n")
    };
    // Each lists the other: a cycle as well as a nesting.
    fs::write(dir.join("outer.pgf"), listing(&["inner.pgf", "Main.mod"])).expect("outer");
    fs::write(dir.join("inner.pgf"), listing(&["outer.pgf"])).expect("inner");
    fs::write(dir.join("Main.mod"), MAIN).expect("module");
    let expected = "error[E0130]: `inner.pgf` is a program file; a program file lists modules, not programs\n \
                    --> outer.pgf:3:13\n";
    let check = rapid_in(&dir, &["check", "outer.pgf"]);
    assert_eq!(check.status.code(), Some(1));
    assert!(stdout(&check).starts_with(expected), "{}", stdout(&check));
    assert!(stdout(&check).contains("found 1 error and 0 warnings"), "{}", stdout(&check));
    let run = rapid_in(&dir, &["run", "outer.pgf"]);
    assert_eq!(run.status.code(), Some(1));
    assert!(stderr(&run).starts_with(expected), "{}", stderr(&run));
}
