//! The shipped examples run as their READMEs and comments say.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn rapid(args: &[&str]) -> Output {
    let home = Path::new(env!("CARGO_TARGET_TMPDIR")).join("examples-home");
    let mut all = vec!["run", "--home", home.to_str().expect("utf-8 path")];
    all.extend_from_slice(args);
    Command::new(env!("CARGO_BIN_EXE_rapid")).current_dir(root()).args(&all).output().expect("run rapid")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The cycle time `rapid run` reports on stderr.
fn cycle_time(stderr: &str) -> f64 {
    let line = stderr.lines().find(|l| l.starts_with("cycle time")).expect("a cycle time line");
    let seconds = line.split(": ").nth(1).and_then(|rest| rest.split(' ').next()).expect("seconds");
    seconds.parse().expect("a number")
}

#[test]
fn the_pick_and_place_cell_places_four_parts() {
    let out = rapid(&["--stimulus", "examples/pick_and_place_cell/parts.stim", "examples/pick_and_place_cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "Parts placed: 4\n");
    let stderr = text(&out.stderr);
    let cycle = cycle_time(&stderr);
    // A lower bound from the program and the stimulus alone: the first part is there
    // at 0.5 s; each part needs its 0.3 s grip and 0.2 s release waits, and four
    // 100 mm straight moves, two at 200 mm/s (0.5 s each) and two at 500 mm/s (0.2 s),
    // so 0.5 + 4 * (0.5 + 1.4) = 8.1 s even with infinite acceleration and no joint
    // moves. An upper bound: each of the 26 moves of at most 2 m at the slowest
    // programmed speed (200 mm/s) takes at most 10 s plus its ramps, and the waits
    // for parts add at most 1.2 s each: 260 + 2 + 5 < 300 s.
    assert!((8.1..300.0).contains(&cycle), "cycle time {cycle} s out of bounds: {stderr}");
    assert!(stderr.contains("IRB 2600-12/1.65"), "{stderr}");
}

#[test]
fn the_press_cell_project_and_backup_run_the_same() {
    let backup = rapid(&["--stimulus", "examples/press_cell.stimulus", "examples/press_cell"]);
    let project = rapid(&["--stimulus", "examples/press_cell.stimulus", "examples/press_cell_project"]);
    assert_eq!(backup.status.code(), Some(0), "{}", text(&backup.stderr));
    assert_eq!(text(&backup.stdout), text(&project.stdout));
}

#[test]
fn a_module_alone_runs_with_virtual_io_like_its_cell() {
    // The same module, robot and stimulus as the cell, with the two signals made
    // virtual from its AliasIO calls instead of configured: the same run.
    let cell = rapid(&["--stimulus", "examples/pick_and_place_cell/parts.stim", "examples/pick_and_place_cell"]);
    let alone = rapid(&[
        "--virtual-io",
        "--robot",
        "IRB 2600-12/1.65",
        "--stimulus",
        "examples/pick_and_place_cell/parts.stim",
        "examples/pick_and_place.mod",
    ]);
    assert_eq!(alone.status.code(), Some(0), "{}", text(&alone.stderr));
    assert_eq!(text(&alone.stdout), "Parts placed: 4\n");
    assert_eq!(cycle_time(&text(&alone.stderr)), cycle_time(&text(&cell.stderr)));
    // Without the option the signals do not exist: the controller's error.
    let refused = rapid(&["examples/pick_and_place.mod"]);
    assert_eq!(refused.status.code(), Some(1));
    assert!(text(&refused.stderr).contains("ERR_ALIASIO_DEF"), "{}", text(&refused.stderr));
}
