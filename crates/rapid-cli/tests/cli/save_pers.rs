//! `rapid run --save-pers` never loses a module: the process is killed (SIGKILL) again
//! and again while it saves a large module, and each time the file must be exactly the
//! old text or exactly the new one (never torn, never empty), and nothing it leaves
//! behind may be loaded as a module.

#![cfg(unix)]

use std::fs;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::fixture::{scratch_in, Scratch};

/// A fresh, empty scratch folder for one test.
fn fresh_dir(name: &str) -> Scratch {
    scratch_in("save_pers", name)
}

/// Elements of the persistent array: about 280 KB of module text.
const N: u32 = 40_000;
/// Runs killed at varied moments.
const RUNS: u32 = 30;

/// The module after `k` runs, written out by hand: each run adds one to `n` and sets
/// `v{i}` to n × 100000 + i. Saved values are written as the controller writes them:
/// an array as `[a,b,...]` without spaces, whole nums without a decimal point. All
/// values stay below 2^24, so num (single precision) holds them exactly.
fn module_text(k: u32) -> String {
    let values: Vec<String> = (1..=N).map(|i| (k * 100_000 + i).to_string()).collect();
    format!(
        "MODULE big\n  ! Every run adds one to n and rewrites v.\n  PERS num n := {k};\n  PERS num v{{{N}}} := [{}];\n  PROC main()\n    n := n + 1;\n    FOR i FROM 1 TO Dim(v, 1) DO\n      v{{i}} := n * 100000 + i;\n    ENDFOR\n  ENDPROC\nENDMODULE\n",
        values.join(",")
    )
}

/// `rapid run --save-pers DIR`: the folder, so that any leftover file with a module
/// extension would be loaded too (and break the run with a duplicate module).
fn start(dir: &Path) -> Child {
    Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(["run", "--save-pers"])
        .arg(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("start rapid")
}

/// A small xorshift generator: varied but reproducible kill moments.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0 % n.max(1)
    }
}

/// Waits until the child's temporary file exists (the save is under way) or the
/// child has ended; at most `limit`.
fn wait_for_save(child: &mut Child, temp: &Path, limit: Duration) {
    let start = Instant::now();
    while !temp.exists() && start.elapsed() < limit {
        if matches!(child.try_wait(), Ok(Some(_))) {
            return;
        }
        std::hint::spin_loop();
    }
}

/// Every entry of the folder is the module or a hidden temporary file of a killed
/// save (`.big.mod.PID-N.tmp`), which no loader takes for a module. Returns how many
/// temporary files there are.
fn check_folder(dir: &Path) -> usize {
    let mut temps = 0;
    for entry in fs::read_dir(dir).expect("read folder") {
        let name = entry.expect("entry").file_name().to_string_lossy().into_owned();
        if name == "big.mod" {
            continue;
        }
        assert!(name.starts_with(".big.mod.") && name.ends_with(".tmp"), "unexpected file `{name}` left behind");
        temps += 1;
    }
    temps
}

#[test]
// The tally of outcomes is printed for `--nocapture`: how many kills hit a save.
#[allow(clippy::print_stderr)]
fn a_save_killed_at_any_moment_leaves_the_old_or_the_new_module() {
    let dir = fresh_dir("kill");
    let module = dir.join("big.mod");
    fs::write(&module, module_text(0)).expect("write module");

    // One run to the end: how long a run takes, and that it saves what we expect.
    let begun = Instant::now();
    let status = start(&dir).wait().expect("wait");
    let full = begun.elapsed();
    assert!(status.success(), "an uninterrupted run failed");
    assert_eq!(fs::read_to_string(&module).expect("read"), module_text(1));

    let mut k = 1;
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut saved, mut mid_save, mut temps_left) = (0, 0, 0);
    for run in 0..RUNS {
        let old = module_text(k);
        let new = module_text(k + 1);
        let mut child = start(&dir);
        let temp = dir.join(format!(".big.mod.{}-0.tmp", child.id()));
        if run % 2 == 0 {
            // Into the save: once the temporary file is there, after 0–0.8 ms (while it
            // is written, flushed or renamed).
            wait_for_save(&mut child, &temp, Duration::from_secs(10));
            std::thread::sleep(Duration::from_micros(rng.below(800)));
        } else {
            // Anywhere in the second half of the run (loading, running, saving) or
            // just after it ended.
            let micros = u64::try_from(full.as_micros()).unwrap_or(u64::MAX);
            std::thread::sleep(Duration::from_micros(micros / 2 + rng.below(micros * 3 / 5)));
        }
        let _ = child.kill(); // SIGKILL; it may have ended already.
        child.wait().expect("reap");
        if temp.exists() {
            mid_save += 1;
        }
        let text = fs::read(&module).expect("the module is always there");
        if text == new.as_bytes() {
            k += 1;
            saved += 1;
        } else {
            assert!(
                text == old.as_bytes(),
                "run {run}: the module is torn ({} bytes; old {}, new {})",
                text.len(),
                old.len(),
                new.len()
            );
        }
        temps_left = check_folder(&dir);
    }
    eprintln!(
        "{RUNS} killed runs: {saved} saved, {} kept the old text; {mid_save} killed mid-save; {temps_left} temporary files left",
        RUNS - saved
    );
    assert!(mid_save > 0, "no kill landed during a save: the test proved nothing");

    // The leftovers are harmless: the folder still loads as one module and saves.
    let status = start(&dir).wait().expect("wait");
    assert!(status.success(), "the folder with leftover temporary files no longer runs");
    assert_eq!(fs::read_to_string(&module).expect("read"), module_text(k + 1));
    fs::remove_dir_all(&dir).expect("clean up");
}

#[test]
fn a_saved_module_keeps_its_permissions() {
    use std::os::unix::fs::PermissionsExt;
    let dir = fresh_dir("perms");
    let module = dir.join("m.mod");
    fs::write(&module, "MODULE m\n  PERS num count := 1;\n  PROC main()\n    Incr count;\n  ENDPROC\nENDMODULE\n")
        .expect("write module");
    fs::set_permissions(&module, fs::Permissions::from_mode(0o600)).expect("chmod");
    let out =
        Command::new(env!("CARGO_BIN_EXE_rapid")).args(["run", "--save-pers"]).arg(&module).output().expect("run");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(
        fs::read_to_string(&module).expect("read"),
        "MODULE m\n  PERS num count := 2;\n  PROC main()\n    Incr count;\n  ENDPROC\nENDMODULE\n"
    );
    assert_eq!(fs::metadata(&module).expect("stat").permissions().mode() & 0o7777, 0o600);
    assert_eq!(fs::read_dir(&dir).expect("read folder").count(), 1, "a temporary file was left behind");
    fs::remove_dir_all(&dir).expect("clean up");
}

#[test]
fn the_save_instruction_replaces_the_module_the_same_way() {
    use std::os::unix::fs::PermissionsExt;
    let dir = fresh_dir("instruction");
    let home = dir.join("home");
    fs::create_dir_all(home.join("HOME")).expect("HOME device");
    let tool = home.join("HOME").join("tool.mod");
    fs::write(
        &tool,
        "MODULE tool\n  PERS num uses := 4;\n  PROC tool_use()\n    uses := uses + 1;\n  ENDPROC\nENDMODULE\n",
    )
    .expect("write module");
    fs::set_permissions(&tool, fs::Permissions::from_mode(0o640)).expect("chmod");
    let main = dir.join("m.mod");
    fs::write(&main, "MODULE m\n  PROC main()\n    Load \"HOME:/tool.mod\";\n    %\"tool_use\"%;\n    Save \"tool\";\n  ENDPROC\nENDMODULE\n")
        .expect("write module");
    let out =
        Command::new(env!("CARGO_BIN_EXE_rapid")).args(["run", "--home"]).arg(&home).arg(&main).output().expect("run");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // Save writes the module with its persistent's current value (manual 1.2.2).
    assert_eq!(
        fs::read_to_string(&tool).expect("read"),
        "MODULE tool\n  PERS num uses := 5;\n  PROC tool_use()\n    uses := uses + 1;\n  ENDPROC\nENDMODULE\n"
    );
    assert_eq!(fs::metadata(&tool).expect("stat").permissions().mode() & 0o7777, 0o640);
    assert_eq!(fs::read_dir(home.join("HOME")).expect("read folder").count(), 1, "a temporary file was left behind");
    fs::remove_dir_all(&dir).expect("clean up");
}

#[test]
fn a_module_that_cannot_be_saved_costs_the_others_nothing() {
    use std::os::unix::fs::PermissionsExt;
    let dir = fresh_dir("partial");
    let (a, b) = (dir.join("a.mod"), dir.join("b.mod"));
    let a_text = "MODULE a\n  PERS num x := 1;\n  PROC main()\n    x := 2;\n    y := 3;\n  ENDPROC\nENDMODULE\n";
    fs::write(&a, a_text).expect("write a");
    fs::write(&b, "MODULE b\n  PERS num y := 1;\nENDMODULE\n").expect("write b");
    // A read-only module is not replaced behind its owner's back.
    fs::set_permissions(&a, fs::Permissions::from_mode(0o444)).expect("chmod");
    let out = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(["run", "--save-pers", "--elog"])
        .arg(dir.join("log.jsonl"))
        .arg(&a)
        .arg(&b)
        .output()
        .expect("run");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("a.mod") && stderr.contains("read-only"), "{stderr}");
    assert_eq!(fs::read_to_string(&a).expect("read a"), a_text);
    assert_eq!(fs::read_to_string(&b).expect("read b"), "MODULE b\n  PERS num y := 3;\nENDMODULE\n");
    // The event log is written all the same: the program logged nothing, so it holds
    // the controller's three state changes (PP reset, started, stopped) only.
    let log = fs::read_to_string(dir.join("log.jsonl")).expect("the log");
    let codes: Vec<&str> = log.lines().filter_map(|l| l.split("\"code\":").nth(1)?.split(',').next()).collect();
    assert_eq!(codes, ["10002", "10150", "10151"], "{log}");
    fs::set_permissions(&a, fs::Permissions::from_mode(0o644)).expect("chmod");
    fs::remove_dir_all(&dir).expect("clean up");
}
