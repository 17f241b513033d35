//! What the tests of multi-task systems share: a backup folder with one RAPID/TASKn
//! folder per task and its SYS.cfg, and how they run `rapid` on it.
// Each test file uses a part of it.
#![allow(dead_code)]

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};

/// A fresh, empty scratch folder `name` of test group `group`.
pub(crate) fn scratch_in(group: &str, name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(group).join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

pub(crate) fn rapid_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rapid")).current_dir(dir).args(args).output().expect("run rapid")
}

/// `rapid ARGS…` started in `dir` with stdout and stderr piped, for a test that talks
/// to the run while it goes on (a socket peer, a signal).
pub(crate) fn spawn_in(dir: &Path, args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_rapid"))
        .current_dir(dir)
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start rapid")
}

pub(crate) fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// A task of a test system: its CAB_TASKS attributes (after -Name) and its module.
pub(crate) struct TaskDef<'a> {
    pub name: &'a str,
    pub attrs: &'a str,
    pub module: &'a str,
}

/// Writes backup `sys` in `dir`: one RAPID/TASKn folder per task, in order, and
/// SYS.cfg (and EIO.cfg when signals are given).
pub(crate) fn system(dir: &Path, tasks: &[TaskDef<'_>], eio_signals: &str) -> PathBuf {
    let root = dir.join("sys");
    let mut sys = String::from("SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n");
    for (n, task) in tasks.iter().enumerate() {
        sys.push_str(&format!("\n      -Name \"{}\" {}\n", task.name, task.attrs));
        let folder = root.join(format!("RAPID/TASK{}/PROGMOD", n + 1));
        fs::create_dir_all(&folder).expect("task folder");
        fs::write(folder.join("Main.mod"), task.module).expect("module");
    }
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    if !eio_signals.is_empty() {
        fs::write(root.join("SYSPAR/EIO.cfg"), format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{eio_signals}"))
            .expect("EIO.cfg");
    }
    root
}
