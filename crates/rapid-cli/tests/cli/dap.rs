//! `rapid dap` end to end with a real DAP client: VS Code's adapter test library
//! (`@vscode/debugadapter-testsupport`, pinned, from npm, installed once per target
//! folder) drives `dap_client.cjs` through a whole session on a two-task manifest.
//!
//! Without node, npm or the registry the test is skipped loudly; under CI (`CI=true`
//! or `OPENRAPID_REQUIRE_DAP_CLIENT=1`) it fails instead.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::fixture::{copy_dir, repo_root, scratch_in, text};

/// The client library the test installs.
const PACKAGE: &str = "@vscode/debugadapter-testsupport@1.68.0";

fn required() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true")
        || std::env::var("OPENRAPID_REQUIRE_DAP_CLIENT").is_ok_and(|v| v == "1")
}

/// Runs `cmd` to its end, at most `limit` (killed after).
fn output_bounded(cmd: &mut Command, limit: Duration) -> Option<Output> {
    let child = cmd.stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().ok()?;
    let id = child.id();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(child.wait_with_output());
    });
    let deadline = Instant::now() + limit;
    match rx.recv_timeout(deadline.saturating_duration_since(Instant::now())) {
        Ok(out) => out.ok(),
        Err(_) => {
            let _ = Command::new("kill").args(["-9", &id.to_string()]).status();
            None
        }
    }
}

/// The folder holding `node_modules` with the pinned client; None (after a loud
/// note) when this machine cannot install it and CI does not require it.
fn client_modules() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("dap-client");
    let marker = dir.join(format!("installed {}", PACKAGE.replace('/', "+")));
    if marker.exists() {
        return Some(dir.join("node_modules"));
    }
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("client folder");
    let mut npm = Command::new("npm");
    npm.args(["install", "--no-audit", "--no-fund", "--silent", "--prefix"]).arg(&dir).arg(PACKAGE);
    let out = output_bounded(&mut npm, Duration::from_secs(600));
    if !out.as_ref().is_some_and(|o| o.status.success()) {
        let why = out.map_or("npm did not start or took too long".to_owned(), |o| text(&o.stderr));
        assert!(!required(), "npm install {PACKAGE} failed (CI requires the DAP client test): {why}");
        #[allow(clippy::print_stderr)]
        {
            eprintln!(
                "*** skipped: npm install {PACKAGE} failed, rapid dap was not tried with a real client: {why} ***"
            );
        }
        return None;
    }
    std::fs::write(&marker, "").expect("marker");
    Some(dir.join("node_modules"))
}

#[test]
fn a_real_dap_client_debugs_a_two_task_program() {
    let node_found = Command::new("node").arg("--version").output().is_ok_and(|o| o.status.success());
    if !node_found {
        assert!(!required(), "node is not installed and CI requires the DAP client test");
        #[allow(clippy::print_stderr)]
        {
            eprintln!("*** skipped: node not installed (rapid dap was not tried with a real client) ***");
        }
        return;
    }
    let Some(modules) = client_modules() else { return };
    let dir = scratch_in("dap", "two_tasks");
    let project = dir.join("project");
    copy_dir(&repo_root().join("crates/rapid-cli/tests/cli/fixtures/dap_project"), &project);
    let script = repo_root().join("crates/rapid-cli/tests/cli/dap_client.cjs");
    let mut node = Command::new("node");
    node.arg(&script).arg(env!("CARGO_BIN_EXE_rapid")).arg(&project).env("NODE_PATH", &modules);
    let out = output_bounded(&mut node, Duration::from_secs(120)).expect("the client finishes within 120 s");
    assert!(out.status.success(), "the DAP session failed:\n{}\n{}", text(&out.stdout), text(&out.stderr));
    assert!(text(&out.stdout).contains("dap session passed"), "{}", text(&out.stdout));
}
