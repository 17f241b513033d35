//! The one fixture of the CLI tests: building and running the `rapid` command, a
//! scratch folder per test that is removed when the test passes, writing files, a
//! backup folder with one RAPID/TASKn folder per task and its SYS.cfg, and the
//! socket peer that talks to a run while it goes on.
//!
//! Every module of the binary uses a part of it; nothing here knows one test's program.
// Each module uses a part of it.
#![allow(dead_code)]

use std::ffi::OsStr;
use std::fs;
use std::io::{BufRead, BufReader, Write};
use std::net::TcpListener;
use std::ops::Deref;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::Duration;

/// The repository's root, where `examples/` and `tests/` are.
pub(crate) fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A fresh, empty folder for one test, removed when it is dropped; a test that fails
/// (its thread panics) leaves the folder behind to look at.
pub(crate) struct Scratch(PathBuf);

impl Scratch {
    pub(crate) fn path(&self) -> &Path {
        &self.0
    }
}

impl Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<OsStr> for Scratch {
    fn as_ref(&self) -> &OsStr {
        self.0.as_os_str()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = fs::remove_dir_all(&self.0);
        }
    }
}

/// A fresh, empty scratch folder `name` of test group `group` (the module's name, so
/// that two modules' tests of one name never share a folder).
pub(crate) fn scratch_in(group: &str, name: &str) -> Scratch {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(group).join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("scratch folder");
    Scratch(dir)
}

/// `rapid ARGS…` as a command, run in `dir` so that messages hold relative paths (for
/// snapshots of its exit code, stdout and stderr).
pub(crate) fn rapid_cmd(dir: &Path, args: &[&str]) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_rapid"));
    cmd.current_dir(dir).args(args);
    cmd
}

/// `rapid ARGS…` run in `dir`, so messages hold relative paths.
pub(crate) fn rapid_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rapid")).current_dir(dir).args(args).output().expect("run rapid")
}

/// `rapid ARGS…` run where the test runs.
pub(crate) fn rapid(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rapid")).args(args).output().expect("run rapid")
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

pub(crate) fn stdout(out: &Output) -> String {
    text(&out.stdout)
}

pub(crate) fn stderr(out: &Output) -> String {
    text(&out.stderr)
}

/// Writes `files` (path relative to `root`, content) into `root`, making folders.
pub(crate) fn write_files(root: &Path, files: &[(&str, &str)]) {
    for (path, content) in files {
        let path = root.join(path);
        fs::create_dir_all(path.parent().expect("parent")).expect("folder");
        fs::write(path, content).expect("write");
    }
}

/// Copies folder `from` with everything in it to `to`.
pub(crate) fn copy_dir(from: &Path, to: &Path) {
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

/// [`system`] of (name, attributes, module) triples and no signals.
pub(crate) fn system_of(dir: &Path, tasks: &[(&str, &str, &str)]) -> PathBuf {
    let tasks: Vec<TaskDef<'_>> = tasks.iter().map(|&(name, attrs, module)| TaskDef { name, attrs, module }).collect();
    system(dir, &tasks, "")
}

/// A task that ticks three times, 0.1 s apart.
pub(crate) const TICKER: &str = "MODULE Ticker\n  PROC main()\n    FOR i FROM 1 TO 3 DO\n      WaitTime 0.1;\n      \
                                 TPWrite \"tick\";\n    ENDFOR\n  ENDPROC\nENDMODULE\n";

/// A two-task backup in `dir`: T_ROB1 runs `client` (with `PORT` replaced), T_B ticks.
pub(crate) fn client_and_ticker(dir: &Path, client: &str, port: u16) {
    let client = client.replace("PORT", &port.to_string());
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: &client },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: TICKER },
    ];
    system(dir, &tasks, "");
}

/// The peer's side of a run whose client waits for data while something else ticks:
/// it accepts the client, sees three `tick` lines on the run's stdout, then sends
/// `hello`, which the client prints (`got hello`) before the run ends well.
pub(crate) fn hello_after_three_ticks(listener: &TcpListener, mut child: Child) {
    let (mut peer, _) = listener.accept().expect("accept");
    peer.set_write_timeout(Some(Duration::from_secs(10))).expect("timeout");
    let mut lines = BufReader::new(child.stdout.take().expect("stdout")).lines();
    let mut seen = Vec::new();
    for _ in 0..3 {
        seen.push(lines.next().and_then(Result::ok).unwrap_or_default());
    }
    assert_eq!(seen, ["tick", "tick", "tick"]);
    peer.write_all(b"hello").expect("send");
    let rest: Vec<String> = lines.map_while(Result::ok).collect();
    let out = child.wait_with_output().expect("rapid ends");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(rest, ["got hello"]);
}
