//! The conformance corpus of `rapid run`: `tests/conformance/NAME.mod` with `NAME.out`
//! (exact stdout), optional `NAME.exit` (exit status, default 0), `NAME.err` (a
//! fragment stderr must contain) and `NAME.args` (extra `rapid run` options). Each
//! program runs with its own empty controller root (`--home`), removed afterwards.
//! Expected outputs were worked out by hand from the manual (see
//! tests/conformance/README.md).
//!
//! `tests/conformance/PENDING` lists programs the interpreter does not pass yet, one
//! name per line with the reason. They are still run: each must FAIL, so a program that
//! starts passing must leave the list (nothing is skipped silently).

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/conformance")
}

struct Outcome {
    passed: bool,
    detail: String,
}

fn run_one(module: &Path) -> Outcome {
    // Optional NAME.args: extra `rapid run` options, separated by whitespace.
    let extra = fs::read_to_string(module.with_extension("args")).unwrap_or_default();
    // A fresh controller root per program, so file tests never write into the repository
    // and never see another program's files.
    let home = fresh_home(module);
    let out = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(["run", "--max-steps", "50000000", "--max-time", "100000"])
        .arg("--home")
        .arg(&home)
        .args(extra.split_whitespace())
        .arg(module)
        .output()
        .expect("run rapid");
    let _ = fs::remove_dir_all(&home);
    let expected_out = fs::read_to_string(module.with_extension("out")).unwrap_or_default();
    let expected_exit: i32 =
        fs::read_to_string(module.with_extension("exit")).ok().and_then(|s| s.trim().parse().ok()).unwrap_or(0);
    let expected_err = fs::read_to_string(module.with_extension("err")).ok();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let exit = out.status.code().unwrap_or(-1);
    let mut problems = Vec::new();
    if stdout != expected_out {
        problems.push(format!("stdout differs:\n--- expected\n{expected_out}--- got\n{stdout}"));
    }
    if exit != expected_exit {
        problems.push(format!("exit status {exit}, expected {expected_exit}"));
    }
    if let Some(fragment) = expected_err {
        if !stderr.contains(fragment.trim()) {
            problems.push(format!("stderr lacks `{}`", fragment.trim()));
        }
    }
    if !problems.is_empty() {
        problems.push(format!("stderr:\n{stderr}"));
    }
    Outcome { passed: problems.is_empty(), detail: problems.join("\n") }
}

/// An empty folder for the controller root of one program.
fn fresh_home(module: &Path) -> PathBuf {
    let name = module.file_stem().unwrap_or_default().to_string_lossy();
    let home = std::env::temp_dir().join(format!("rapid-conformance-{}-{name}", std::process::id()));
    let _ = fs::remove_dir_all(&home);
    fs::create_dir_all(&home).expect("make a controller root");
    home
}

#[test]
fn conformance_corpus() {
    let dir = corpus();
    let mut modules: Vec<PathBuf> = fs::read_dir(&dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.extension().is_some_and(|e| e == "mod")).collect()
        })
        .unwrap_or_default();
    modules.sort();
    assert!(modules.len() >= 150, "expected at least 150 conformance programs, found {}", modules.len());
    let pending_text = fs::read_to_string(dir.join("PENDING")).unwrap_or_default();
    let pending: Vec<&str> =
        pending_text.lines().filter_map(|l| l.split_whitespace().next()).filter(|l| !l.starts_with('#')).collect();
    let mut failures = Vec::new();
    let mut newly_passing = Vec::new();
    let mut passed = 0;
    for module in &modules {
        let name = module.file_stem().unwrap_or_default().to_string_lossy().into_owned();
        let outcome = run_one(module);
        match (outcome.passed, pending.contains(&name.as_str())) {
            (true, false) => passed += 1,
            (true, true) => newly_passing.push(name),
            (false, true) => {}
            (false, false) => failures.push(format!("== {name}\n{}", outcome.detail)),
        }
    }
    assert!(
        failures.is_empty() && newly_passing.is_empty(),
        "{passed} passed; {} failed:\n{}\nnow passing, remove from PENDING: {newly_passing:?}",
        failures.len(),
        failures.join("\n")
    );
}
