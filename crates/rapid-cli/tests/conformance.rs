//! The conformance corpus of `rapid run`: `tests/conformance/NAME.mod` with `NAME.out`
//! (exact stdout), optional `NAME.exit` (exit status, default 0), `NAME.err` (a
//! fragment stderr must contain) and `NAME.args` (extra `rapid run` options). Each
//! program runs with its own empty controller root (`--home`), removed afterwards.
//! Expected outputs were worked out by hand from the manual (see
//! tests/conformance/README.md).
//!
//! Each program is a test of its own, named after it, so that a failure names the
//! program and one program runs alone:
//! `cargo test -p rapid-cli --test conformance -- alias_record --exact`.
//! The runner is `harness = false` on libtest-mimic, which gives the usual test
//! options (`--list`, filters, `--exact`, `--skip`, `--test-threads`) and runs the
//! programs in parallel. New `.mod` files are picked up when the runner starts.
//!
//! `tests/conformance/PENDING` lists programs the interpreter does not pass yet, one
//! name per line with the reason. They are still run: each must FAIL, so a program that
//! starts passing must leave the list (nothing is skipped silently).

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use libtest_mimic::{Arguments, Failed, Trial};

/// The least number of programs the corpus holds; fewer means the runner looked in the
/// wrong place or lost files.
const MIN_PROGRAMS: usize = 150;

fn main() {
    let args = Arguments::from_args();
    let dir = corpus();
    let modules = programs(&dir);
    let pending = pending(&dir);
    let mut trials = vec![corpus_trial(modules.len(), &pending, &modules)];
    for module in modules {
        let name = program_name(&module);
        let is_pending = pending.contains(&name);
        trials.push(Trial::test(name.clone(), move || judge(&name, &module, is_pending)));
    }
    libtest_mimic::run(&args, trials).exit();
}

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/conformance")
}

/// Every `NAME.mod` of the corpus, sorted by name.
fn programs(dir: &Path) -> Vec<PathBuf> {
    let mut modules: Vec<PathBuf> = fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.extension().is_some_and(|e| e == "mod")).collect()
        })
        .unwrap_or_default();
    modules.sort();
    modules
}

/// The names PENDING lists: the first word of each line that is not a `#` comment.
fn pending(dir: &Path) -> Vec<String> {
    let text = fs::read_to_string(dir.join("PENDING")).unwrap_or_default();
    text.lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|l| !l.starts_with('#'))
        .map(str::to_owned)
        .collect()
}

fn program_name(module: &Path) -> String {
    module.file_stem().unwrap_or_default().to_string_lossy().into_owned()
}

/// A test of the corpus as a whole: it holds at least MIN_PROGRAMS programs, and every
/// name PENDING lists is a program (a stale entry would hide nothing but mislead).
fn corpus_trial(count: usize, pending: &[String], modules: &[PathBuf]) -> Trial {
    let names: Vec<String> = modules.iter().map(|m| program_name(m)).collect();
    let stale: Vec<String> = pending.iter().filter(|p| !names.contains(p)).cloned().collect();
    Trial::test("corpus_holds_the_programs_pending_names", move || {
        if count < MIN_PROGRAMS {
            return Err(format!("expected at least {MIN_PROGRAMS} conformance programs, found {count}").into());
        }
        if !stale.is_empty() {
            return Err(format!("PENDING names programs the corpus lacks: {stale:?}").into());
        }
        Ok(())
    })
}

/// Runs one program and judges it: a program passes when it meets every expectation,
/// except a PENDING program, which must fail.
fn judge(name: &str, module: &Path, is_pending: bool) -> Result<(), Failed> {
    let outcome = run_one(module);
    match (outcome.passed, is_pending) {
        (true, false) | (false, true) => Ok(()),
        (true, true) => Err(format!("{name} passes now: remove it from tests/conformance/PENDING").into()),
        (false, false) => Err(format!("== {name}\n{}", outcome.detail).into()),
    }
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
        .output();
    let _ = fs::remove_dir_all(&home);
    let out = match out {
        Ok(out) => out,
        Err(e) => return Outcome { passed: false, detail: format!("cannot run rapid: {e}") },
    };
    // A program without NAME.out must print nothing.
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
    let name = program_name(module);
    let home = std::env::temp_dir().join(format!("rapid-conformance-{}-{name}", std::process::id()));
    let _ = fs::remove_dir_all(&home);
    fs::create_dir_all(&home).expect("make a controller root");
    home
}
