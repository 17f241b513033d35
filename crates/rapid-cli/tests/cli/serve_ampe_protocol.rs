//! abb-motion-program-exec (0.7.4 from PyPI, unmodified, in the virtualenv
//! `serve_ampe.rs` makes) runs motion programs under `rapid serve` on a RAPID system
//! of our own writing that speaks its protocol: `tests/systems/ampe_protocol/`, written
//! from the client's Python (the binary program it uploads to `$RAMDISK`, the event
//! log messages naming the joint log, the log's format), not from the project's RAPID.
//! Unlike `serve_ampe.rs` (the project's own system, gated on a clone) it needs no
//! GitHub: it runs in CI. Without python3, its venv module or PyPI it is skipped
//! loudly; under CI it fails instead (`serve.rs`'s rule).

use std::process::Command;
use std::time::Duration;

use crate::fixture::{copy_dir, repo_root, scratch_in};
use crate::serve::{interrupt, output_bounded, start_server, venv_python, wait_bounded};
use crate::serve_ampe::PACKAGES;

#[test]
fn execute_motion_program_runs_on_our_protocol_system() {
    let Some(python) = venv_python("ampe-client-venv", &PACKAGES) else { return };
    let dir = scratch_in("serve", "ampe_protocol");
    let system = dir.join("ampe_protocol");
    copy_dir(&repo_root().join("tests/systems/ampe_protocol"), &system);
    std::fs::create_dir_all(system.join("RAMDISK")).expect("RAMDISK folder");
    let (mut child, url, _pendant) = start_server(&system.join("config"));
    let script = repo_root().join("crates/rapid-cli/tests/cli/serve_ampe_protocol.py");
    let out = output_bounded(Command::new(&python).arg(&script).arg(&url), Duration::from_secs(180));
    interrupt(&child);
    let status = wait_bounded(&mut child, Duration::from_secs(20));
    let out = out.expect("the client script ends within 180 s");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "the client failed:\n{stdout}\n{stderr}");
    // 11 checks: each program's log, its last row (the final MoveAbsJ's angles within
    // 0.01°) and timestamps; the second's command numbers (each of 1..6, never going
    // back), its first row, its span (at least the WaitTime's 0.2 s); the state.
    assert_eq!(stdout.lines().last(), Some("11 passed, 0 failed"), "{stdout}");
    assert_eq!(status.and_then(|s| s.code()), Some(0));
    // The client read its joint logs back and deleted them; its program file stays.
    let left: Vec<String> = std::fs::read_dir(system.join("RAMDISK"))
        .expect("RAMDISK")
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .collect();
    assert_eq!(left, ["motion_program.bin"], "RAMDISK holds {left:?}");
}
