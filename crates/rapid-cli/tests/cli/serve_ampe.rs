//! abb-motion-program-exec (0.7.4 from PyPI, unmodified, in a virtualenv made here)
//! runs motion programs on its own RAPID system under `rapid serve`: its three tasks
//! (T_ROB1, the logger, the error reporter) booted from its own `config_params/` +
//! `HOME/` layout, driven by `serve_ampe.py` through `execute_motion_program`; and its
//! MultiMove layout (T_ROB1 and T_ROB2) through `execute_multimove_motion_program`.
//!
//! The RAPID system is public code we do not copy into this repository, and PyPI's
//! package holds only the Python client: the test takes the system from
//! `OPENRAPID_AMPE_ROBOT` (the `robot/` folder of a clone of
//! github.com/rpiRobotics/abb_motion_program_exec) and, without it, says loudly that
//! it is skipped and why. The folder is copied to a scratch folder first: the server
//! writes the motion program and its joint log to `RAMDISK/`, and saves persistents
//! into `HOME/` at Ctrl-C. Without python3, its venv module or PyPI the test is skipped
//! as `serve.rs`'s client tests are (under CI it fails instead).

use std::path::PathBuf;
use std::process::Command;
use std::time::Duration;

use crate::fixture::{copy_dir, repo_root, scratch_in};
use crate::serve::{interrupt, output_bounded, start_server, venv_python, wait_bounded};

/// The client and every package it pulls in, pinned (they install on Python 3.11).
pub(super) const PACKAGES: [&str; 16] = [
    "abb-motion-program-exec==0.7.4",
    "abb-robot-client[aio]==0.4.0",
    "numpy==2.4.6",
    "requests==2.34.2",
    "websocket-client==1.9.2",
    "protobuf==7.36.2",
    "httpx==0.28.1",
    "websockets==17.4",
    "anyio==4.16.0",
    "certifi==2026.10.19.post1",
    "charset-normalizer==3.5.3",
    "h11==0.16.0",
    "httpcore==1.0.9",
    "idna==3.20",
    "typing_extensions==4.16.0",
    "urllib3==2.8.0",
];

/// The variable naming the system's `robot/` folder.
const ROBOT_VAR: &str = "OPENRAPID_AMPE_ROBOT";

/// The `robot/` folder `OPENRAPID_AMPE_ROBOT` names; None (after a loud note) when
/// it is not set. A folder without the system's layout fails the test: it was set
/// wrong.
fn robot_folder() -> Option<PathBuf> {
    let Some(robot) = std::env::var_os(ROBOT_VAR) else {
        #[allow(clippy::print_stderr)]
        {
            eprintln!(
                "*** skipped: {ROBOT_VAR} is not set, abb-motion-program-exec was not run against rapid serve. \
                 Its RAPID system is not on PyPI: clone https://github.com/rpiRobotics/abb_motion_program_exec \
                 and set {ROBOT_VAR}=/path/to/abb_motion_program_exec/robot (docs/serve.md) ***"
            );
        }
        return None;
    };
    let robot = PathBuf::from(robot);
    for needed in ["config_params/SYS.cfg", "config_params/EIO.cfg", "HOME/motion_program_exec.mod"] {
        assert!(robot.join(needed).is_file(), "{ROBOT_VAR}={}: no {needed} there", robot.display());
    }
    Some(robot)
}

/// The system copied to a scratch folder, served from its `layout` folder, with
/// `serve_ampe.py URL mode…` run against it: the script's last line, the server's exit
/// code, and the system's folder (kept while the scratch lives).
fn serve_and_drive(name: &str, layout: &str, mode: &[&str]) -> Option<(String, Option<i32>, crate::fixture::Scratch)> {
    let robot = robot_folder()?;
    let python = venv_python("ampe-client-venv", &PACKAGES)?;
    let dir = scratch_in("serve", name);
    let system = dir.join("robot");
    copy_dir(&robot, &system);
    std::fs::create_dir_all(system.join("RAMDISK")).expect("RAMDISK folder");
    let (mut child, url, _pendant) = start_server(&system.join(layout));
    let script = repo_root().join("crates/rapid-cli/tests/cli/serve_ampe.py");
    let out = output_bounded(Command::new(&python).arg(&script).arg(&url).args(mode), Duration::from_secs(180));
    interrupt(&child);
    let status = wait_bounded(&mut child, Duration::from_secs(20));
    let out = out.expect("the client script ends within 180 s");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "the client failed:\n{stdout}\n{stderr}");
    let last = stdout.lines().last().unwrap_or_default().to_owned();
    Some((last, status.and_then(|s| s.code()), dir))
}

#[test]
fn execute_motion_program_runs_on_its_own_system() {
    let Some((last, code, dir)) = serve_and_drive("ampe", "config_params", &[]) else { return };
    let system = dir.join("robot");
    // 14 checks: each program's log and last row, the command numbers, the state.
    assert_eq!(last, "14 passed, 0 failed");
    assert_eq!(code, Some(0));
    // The client read its joint logs back and deleted them; its program file stays.
    let left: Vec<String> = std::fs::read_dir(system.join("RAMDISK"))
        .expect("RAMDISK")
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .collect();
    assert_eq!(left, ["motion_program.bin"], "RAMDISK holds {left:?}");
    // Ctrl-C saved the shared module's persistent once (three tasks share it): the
    // last program was not running, at command 5 (its WaitTime, the last command
    // that sets the number) with all six queued, and stood at its final target.
    let shared = std::fs::read_to_string(system.join("HOME/motion_program_shared.sys")).expect("shared module");
    let saved = "PERS motion_program_state_type motion_program_state{2} := [[FALSE,5,6,0,\"\",";
    assert!(shared.contains(saved), "{shared}");
    assert!(shared.contains("[[10,5,15,-20,50,30],"), "{shared}");
}

#[test]
fn execute_multimove_motion_program_runs_on_its_multimove_layout() {
    let Some((last, code, _dir)) = serve_and_drive("ampe_multimove", "config_params_multimove", &["multimove"]) else {
        return;
    };
    // 11 checks: both robots' last rows in both logs, the command numbers (every one
    // seen, never going back, the last), the state.
    assert_eq!(last, "11 passed, 0 failed");
    assert_eq!(code, Some(0));
}
