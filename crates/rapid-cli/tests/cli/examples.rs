//! The shipped examples run as their READMEs and comments say.

use std::path::Path;
use std::process::Output;

use crate::fixture::{rapid_in, repo_root, text};

fn rapid(args: &[&str]) -> Output {
    let home = Path::new(env!("CARGO_TARGET_TMPDIR")).join("examples-home");
    let mut all = vec!["run", "--home", home.to_str().expect("utf-8 path")];
    all.extend_from_slice(args);
    rapid_in(&repo_root(), &all)
}

/// The cycle time `rapid run` reports on stderr.
fn cycle_time(stderr: &str) -> f64 {
    let line = stderr.lines().find(|l| l.starts_with("cycle time")).expect("a cycle time line");
    let seconds = line.split(": ").nth(1).and_then(|rest| rest.split(' ').next()).expect("seconds");
    seconds.parse().expect("a number")
}

/// The timing model's pieces for the IRB 2600 (docs/semantics.md, "Timing model"):
/// path acceleration 10 m/s² scaled by axis 1's 175 °/s over 250 °/s.
const IRB2600_ACC: f64 = 7_000.0;

/// A MoveL of `length` mm at `v` mm/s from stop to stop (a trapezoid).
fn move_l(length: f64, v: f64) -> f64 {
    length / v + v / IRB2600_ACC
}

/// A MoveJ from stop to stop whose pace is set by the TCP's chord at v1000 (every
/// axis slower than its maximum by `f`, the limiting axis's full-speed time over the
/// chord's time): the chord's time plus the ramps, f · 0.15 s.
fn move_j(chord: f64, f: f64) -> f64 {
    chord / 1000.0 + f * 0.15
}

/// The most a fly-by point can save against stopping there: half of each side's ramp
/// (what a stop costs beyond cruising) and the zone legs `zone`/v on either side that
/// the corner may cut. `ramp_in`, `ramp_out` are whole ramp times.
fn corner_saving(ramp_in: f64, ramp_out: f64, zone: f64, v_in: f64, v_out: f64) -> f64 {
    (ramp_in + ramp_out) / 2.0 + zone / v_in + zone / v_out
}

#[test]
fn the_pick_and_place_cell_places_four_parts_in_the_time_the_timing_model_gives() {
    let io_log = Path::new(env!("CARGO_TARGET_TMPDIR")).join("pick_and_place_io.csv");
    let out = rapid(&[
        "--io-log",
        io_log.to_str().expect("utf-8"),
        "--stimulus",
        "examples/pick_and_place_cell/parts.stim",
        "examples/pick_and_place_cell",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "Parts placed: 4\n");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("IRB 2600-12/1.65"), "{stderr}");
    // Worked out by hand. The joints come from an independent OPW calculation
    // (tests/hand/pick_and_place.py) with the IRB 2600-12/1.65's parameters (a1 150, a2 -115, c1 445, c2 700, c3 795, c4 85)
    // and the targets' TCPs (tVacuum 142.5 mm along the flange's z, pointing down):
    //   start (all axes 0): TCP [1172.5, 0, 1260]
    //   pHome [600, 0, 900]:          [0, -29.968, 32.764, 0, 87.204, 0]
    //   pick approach [1070,-365,425]: [-18.836, 25.299, 14.907, 0, 49.795, -18.836]
    //   place approach n [650, 500 + 110n, 240] (turned 90° about z):
    //     n 0 [37.569, 16.346, 45.805, 0, 27.849, -52.431]
    //     n 1 [43.182, 20.615, 39.580, 0, 29.805, -46.818]
    //     n 2 [47.925, 25.220, 32.506, 0, 32.273, -42.075]
    //     n 3 [51.934, 30.140, 24.610, 0, 35.250, -38.066]
    // Every MoveJ is paced by its TCP chord at v1000 (its limiting axis, at 175 °/s,
    // would be faster; the 90° reorientations at 500 °/s take 0.18 s): the chord (mm),
    // and f = the limiting axis's full-speed time over the chord's time.
    let home = (676.281, 0.242234 / 0.676281); // start → pHome, axis 5
    let to_pick_first = (761.413, 0.315810 / 0.761413); // pHome → pick approach, axis 2
    let place = [(979.209, 0.322310), (1077.613, 0.354385), (1178.070, 0.381489), (1280.098, 0.404400)];
    let to_place = |n: usize| (place[n].0, place[n].1 / (place[n].0 / 1000.0)); // pick approach ↔ place n
    let last = (1061.603, 0.343478 / 1.061603); // place approach 3 → pHome, axis 2
    let j = |(chord, f): (f64, f64)| move_j(chord, f);
    let (down, up) = (move_l(100.0, 200.0), move_l(100.0, 500.0));
    // The program. A part is there at 0.5 s; after a part is placed (Reset), the next
    // one is there 1.2 s later, when the robot has long stood above the pallet: the
    // MoveL up before WaitDI becomes a stop point (three corner path failures) and the
    // next pick starts when the part is there. Stopping at every point (fine points
    // settle 0.05 s) gives the upper bound:
    let settle = 0.05;
    let pick_chain = |to_pick: f64| to_pick + down + settle;
    let place_chain = |n: usize| up + j(to_place(n)) + down + settle;
    let mut upper = j(home).max(0.5);
    for n in 0..4 {
        let to_pick = if n == 0 { j(to_pick_first) } else { j(to_place(n - 1)) };
        let start = if n == 0 { upper } else { upper + 1.2 };
        upper = start + pick_chain(to_pick) + 0.3;
        upper += place_chain(n);
    }
    upper += 0.2 + up + j(last) + settle;
    // The fly-by points that are not stop points can each save at most
    // `corner_saving`; a MoveJ's ramp is f · 0.15 s, a MoveL's v / 7000 s².
    let ramp_j = |(_, f): (f64, f64)| f * 0.15;
    let (ramp_200, ramp_500) = (200.0 / IRB2600_ACC, 500.0 / IRB2600_ACC);
    let pick_saving = |to_pick: (f64, f64)| corner_saving(ramp_j(to_pick), ramp_200, 20.0, 1000.0, 200.0);
    let place_saving = |n: usize| {
        corner_saving(ramp_500, ramp_j(to_place(n)), 20.0, 500.0, 1000.0)
            + corner_saving(ramp_j(to_place(n)), ramp_200, 20.0, 1000.0, 200.0)
    };
    let mut saving = corner_saving(ramp_j(home), ramp_j(to_pick_first), 50.0, 1000.0, 1000.0);
    for n in 0..4 {
        saving += pick_saving(if n == 0 { to_pick_first } else { to_place(n - 1) }) + place_saving(n);
    }
    saving += corner_saving(ramp_500, ramp_j(last), 20.0, 500.0, 1000.0);
    let cycle = cycle_time(&stderr);
    assert!((upper - saving..=upper).contains(&cycle), "cycle time {cycle} s, expected {} … {upper} s", upper - saving);
    assert!(stderr.contains("3 corner path failure(s)"), "{stderr}");
    // Each pick and each place, from the move that starts it to the vacuum's change,
    // within its own bounds (the corners inside each chain only).
    let changes = io_changes(&io_log);
    let times = |value: &str| -> Vec<f64> {
        changes.iter().filter(|(_, s, v)| s == "DO_Vacuum" && v == value).map(|(t, _, _)| *t).collect()
    };
    let (on, off) = (times("1"), times("0"));
    // (Reset at the start changes nothing: the output is 0 already.)
    assert_eq!((on.len(), off.len()), (4, 4), "{changes:?}");
    for n in 1..4 {
        // The pick starts 1.2 s after the part before was let go.
        let took = on[n] - (off[n - 1] + 1.2);
        let to_pick = to_place(n - 1);
        let (chain, save) = (pick_chain(j(to_pick)), pick_saving(to_pick));
        assert!(
            (chain - save - 0.002..=chain + 0.002).contains(&took),
            "pick {n}: {took} s, expected {chain} - {save}"
        );
    }
    for n in 0..4 {
        // The place starts when the 0.3 s grip wait after the vacuum went on ends.
        let took = off[n] - (on[n] + 0.3);
        let (chain, save) = (place_chain(n), place_saving(n));
        assert!(
            (chain - save - 0.002..=chain + 0.002).contains(&took),
            "place {n}: {took} s, expected {chain} - {save}"
        );
    }
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

/// The `(time, signal, new value)` rows of an `--io-log` file.
fn io_changes(path: &Path) -> Vec<(f64, String, String)> {
    let log = std::fs::read_to_string(path).expect("the I/O log");
    log.lines()
        .skip(1)
        .map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            (fields[0].parse().expect("a time"), fields[1].to_owned(), fields[3].to_owned())
        })
        .collect()
}

fn assert_near(actual: f64, expected: f64, tolerance: f64, what: &str) {
    assert!((actual - expected).abs() <= tolerance, "{what}: {actual} s, expected {expected} ± {tolerance} s");
}

/// A stop-point MoveL of `length` mm at `v` mm/s on the IRB 120: the trapezoid of the
/// timing model (path acceleration 10 m/s², `crates/rapid-motion/src/plan/limits.rs`),
/// L/v + v/a when the move reaches its speed, plus the 0.05 s a `fine` point settles.
fn fine_move_l(length: f64, v: f64) -> f64 {
    const ACC: f64 = 10_000.0;
    let ramps = if length >= v * v / ACC { length / v + v / ACC } else { 2.0 * (length / ACC).sqrt() };
    ramps + 0.05
}

#[test]
fn the_welding_example_welds_its_seam_in_the_time_the_timing_model_gives() {
    let io_log = Path::new(env!("CARGO_TARGET_TMPDIR")).join("welding_io.csv");
    let out = rapid(&["--io-log", io_log.to_str().expect("utf-8"), "examples/welding"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // Worked out by hand (IRB 120, tTorch 150 mm along the flange's z):
    // 1. MoveAbsJ [0,0,0,0,0,0] → jHome turns axis 5 by 90° (max 320 °/s: 0.28125 s
    //    at full speed, ramps of 0.15 s); the TCP swings on a 222 mm radius (72 mm
    //    wrist + 150 mm tool), a 313.96 mm chord, so v1000 caps the pace at
    //    0.28125 · 1000 / 313.96 = 0.8958 of full speed: 0.28125/0.8958 + 0.8958 · 0.15
    //    = 0.44833 s, + 0.05 s settle.
    let home = 0.28125 / 0.8958 + 0.8958 * 0.15 + 0.05;
    // 2. From home's TCP [302,0,408] to 50 mm above the seam start [300,-100,250]:
    //    √(2² + 100² + 158²) = 186.997 mm at v500; 3. down 50 mm at v100.
    let approach = fine_move_l(186.997, 500.0) + fine_move_l(50.0, 100.0);
    // 4. The seam: 200 mm straight, then the half circle of radius 40 mm (125.664 mm),
    //    tangent to it, at 20 mm/s as one stretch (the z1 corner between them is
    //    tangent: no time of its own).
    let seam = fine_move_l(200.0 + std::f64::consts::PI * 40.0, 20.0);
    // 5. Up 50 mm at v200; 6. to the cleaner [200,250,300] from [380,100,250]:
    //    √(180² + 150² + 50²) = 239.583 mm at v500; WaitTime 1; 7. home's TCP from
    //    the cleaner: √(102² + 250² + 108²) = 290.806 mm at v500.
    let rest = fine_move_l(50.0, 200.0) + fine_move_l(239.583, 500.0) + 1.0 + fine_move_l(290.806, 500.0);
    let seam_start = home + approach;
    let expected = seam_start + seam + rest;
    assert_near(cycle_time(&text(&out.stderr)), expected, 0.01, "cycle time");
    // ClkRead from the seam's start to its stop (after the settle), to the ms.
    let seam_time: f64 = text(&out.stdout).trim().trim_start_matches("Seam welded in ").parse().expect("a time");
    assert_near(seam_time, seam, 0.0015, "seam time");
    let changes = io_changes(&io_log);
    let times = |signal: &str, value: &str| -> Vec<f64> {
        changes.iter().filter(|(_, s, v)| s == signal && v == value).map(|(t, _, _)| *t).collect()
    };
    // The arc: on where the seam starts (TriggIO \Start 0), off where the robot stops
    // at its end (before the settle time).
    assert_eq!(times("doArcOn", "1").len(), 1, "{changes:?}");
    assert_near(times("doArcOn", "1")[0], seam_start, 0.002, "arc on");
    assert_near(times("doArcOn", "0")[0], seam_start + seam - 0.05, 0.002, "arc off");
    // The cleaner's zone (x 150..250, y 200..300, z 250..350): move 6 enters it where
    // x falls to 250, 72.22 % of the way (173.03 mm): 0.05 s to reach 500 mm/s over
    // 12.5 mm, then 160.53 mm at 500 mm/s; move 7 leaves it where y falls to 200, 20 %
    // of the way (58.16 mm). The zone is checked every 4 ms.
    let to_cleaner = seam_start + seam + fine_move_l(50.0, 200.0);
    assert_near(times("doAtCleaner", "1")[0], to_cleaner + 0.05 + 160.53 / 500.0, 0.005, "into the cleaner zone");
    let from_cleaner = to_cleaner + fine_move_l(239.583, 500.0) + 1.0;
    assert_near(times("doAtCleaner", "0")[0], from_cleaner + 0.05 + 45.66 / 500.0, 0.005, "out of the cleaner zone");
}

#[test]
fn the_palletizing_example_stacks_twelve_boxes_in_the_time_the_timing_model_gives() {
    let io_log = Path::new(env!("CARGO_TARGET_TMPDIR")).join("palletizing_io.csv");
    let out = rapid(&["--io-log", io_log.to_str().expect("utf-8"), "examples/palletizing"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "Layer 1\nLayer 2\nBoxes on the pallet: 12\n");
    // Worked out by hand (IRB 120, tGripper 100 mm): MoveAbsJ to jHome turns axis 5
    // by 90° at full speed (the TCP's 243.24 mm chord at v1000 does not limit it):
    // 0.28125 + 0.15 ramps + 0.05 settle; then MoveL to the pick place
    // √(52² + 250² + 308²) = 400.085 mm at 400 mm/s.
    let first_grip = 0.28125 + 0.15 + 0.05 + fine_move_l(400.085, 400.0);
    // Each transfer is up 100 mm, across, down 100 mm at 400 mm/s through two z20
    // corners. Where the work object stays the same the corner is a TCP parabola
    // that needs no slow-down (90° at 20 mm allows √(10000 · 20 / sin 45°) =
    // 532 mm/s) and takes as long as the straight path it replaces; where it changes,
    // see `joint_corners_ms` below. Across: from above the pick place [250,-250,250]
    // to above the place [200 + x, 100 + y, 250 + 50 · (layer - 1)].
    let places = [(0.0, 0.0), (80.0, 0.0), (0.0, 80.0), (80.0, 80.0), (0.0, 160.0), (80.0, 160.0)];
    let transfer = |layer: f64, (x, y): (f64, f64)| {
        let across = ((x - 50.0f64).powi(2) + (y + 350.0f64).powi(2) + (50.0 * (layer - 1.0)).powi(2)).sqrt();
        fine_move_l(200.0 + across, 400.0)
    };
    // §2.2.3: where the work object changes (wobj0 ↔ wobjPallet above the pick place
    // going out, above the place coming back: 23 corners) the corner is joint-
    // interpolated: a blend in the metric of each axis over its maximum speed
    // (250, 250, 250, 320, 320, 420 °/s), from 20 mm before the point to 20 mm after
    // it, time 2/(v0/(2·L_in) + v1/(2·L_out)) with L the legs and v the ends' speeds
    // in that metric, each end at most √(a·L/sin(θ/2)) (a the 10 m/s² path
    // acceleration in the metric, θ the turn), the TCP braking to it before and
    // speeding up after: (400 − v_e)²/(2·a·400) each. Against the 0.1 s TCP parabola,
    // per box out and back (ms), from an independent OPW calculation of the IRB 120's
    // joints at the corners' ends, tests/hand/palletizing_corners.py (e.g. layer 1,
    // box 0, out: θ 95.8°, the exit's 0.434 over its 0.395 limit):
    let joint_corners_ms = [
        5.35, -1.76, 0.42, -0.62, 4.78, -1.19, 0.42, 0.03, 4.38, -0.01, 0.60, 6.87, // layer 1
        3.09, 0.44, 0.34, -0.01, 2.98, -0.56, 0.36, 0.66, 2.89, 3.52, 0.37, // layer 2
    ];
    let joint_corner = |n: usize| joint_corners_ms[n] / 1000.0;
    let mut t = first_grip;
    let mut expected_changes = Vec::new();
    for (k, (layer, place)) in [1.0, 2.0].iter().flat_map(|&l| places.iter().map(move |&p| (l, p))).enumerate() {
        expected_changes.push((t, "1"));
        t += 0.2 + transfer(layer, place) + joint_corner(2 * k);
        expected_changes.push((t, "0"));
        t += 0.2;
        if k < 11 {
            t += transfer(layer, place) + joint_corner(2 * k + 1);
        }
    }
    // After the last box: up 100 mm (fine), then across to above the pick place
    // (513.323 mm) and on to home's TCP [302,0,458] (329.345 mm) through a z20
    // corner of 146° (allows 458 mm/s).
    t += fine_move_l(100.0, 400.0) + fine_move_l(513.323 + 329.345, 400.0);
    assert_near(cycle_time(&text(&out.stderr)), t, 0.02, "cycle time");
    let grips: Vec<(f64, String)> =
        io_changes(&io_log).into_iter().filter(|(_, s, _)| s == "doGrip").map(|(t, _, v)| (t, v)).collect();
    assert_eq!(grips.len(), expected_changes.len(), "{grips:?}");
    for ((actual, value), (expected, expected_value)) in grips.iter().zip(&expected_changes) {
        assert_eq!(value, expected_value);
        assert_near(*actual, *expected, 0.01, "doGrip change");
    }
}

#[test]
fn the_twin_robots_carry_their_part_in_step() {
    let out = rapid(&["--quiet", "examples/twin_robots"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // Worked by hand (IRB 120, 10 m/s², 0.05 s settle at each fine point): lift 100 mm
    // at v200, 0.5 + 0.02 = 0.52 s; carry 150 mm (left) and 100 mm (right), both take
    // the left's 0.75 + 0.02 = 0.77 s; lower 0.52 s: 0.57 + 0.82 + 0.57 = 1.96 s in
    // both tasks (the right alone would need 1.71 s).
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(lines, ["T_ROB1 carried the part in 1.96", "T_ROB2 carried the part in 1.96"]);
}

#[test]
fn the_conveyor_example_picks_moving_boxes_when_the_timing_model_says() {
    let io_log = Path::new(env!("CARGO_TARGET_TMPDIR")).join("conveyor_io.csv");
    let out = rapid(&[
        "--io-log",
        io_log.to_str().expect("utf-8"),
        "--stimulus",
        "examples/conveyor_tracking/boxes.stim",
        "examples/conveyor_tracking",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "Boxes stacked: 3\n");
    // Worked by hand (IRB 120, tool0; boxes at the switch at 0.5 s and 3.5 s, moving at
    // 100 mm/s along x from (250, 0, 300); the table's stack at (300, -200, 250)).
    // Box 1: connected at 0.5 s, above it 50 mm from home at v500, down 80 mm at v200:
    // grip. 0.2 s, up 80 mm at v500; the box has travelled 100 · (t - 0.5) mm, so the
    // robot leaves it at (250 + that, 0, 400) for the point 130 mm above the stack.
    let grip1 = 0.5 + fine_move_l(50.0, 500.0) + fine_move_l(80.0, 200.0);
    let leave1 = grip1 + 0.2 + fine_move_l(80.0, 500.0);
    let from1 = 250.0 + 100.0 * (leave1 - 0.5);
    let across1 = ((from1 - 300.0).powi(2) + 200.0f64.powi(2) + 20.0f64.powi(2)).sqrt();
    let release1 = leave1 + fine_move_l(across1, 500.0) + fine_move_l(130.0, 200.0);
    // Up 130 mm, then wait for box 2 at 3.5 s and go above it: from (300, -200, 380) to
    // (250, 0, 400).
    let up1 = release1 + 0.2 + fine_move_l(130.0, 500.0);
    assert!(up1 < 3.5, "the robot waits for box 2 ({up1} s)");
    let above2 = (50.0f64.powi(2) + 200.0f64.powi(2) + 20.0f64.powi(2)).sqrt();
    let grip2 = 3.5 + fine_move_l(above2, 500.0) + fine_move_l(80.0, 200.0);
    let leave2 = grip2 + 0.2 + fine_move_l(80.0, 500.0);
    let from2 = 250.0 + 100.0 * (leave2 - 3.5);
    let across2 = ((from2 - 300.0).powi(2) + 200.0f64.powi(2) + 10.0f64.powi(2)).sqrt();
    let release2 = leave2 + fine_move_l(across2, 500.0) + fine_move_l(130.0, 200.0);
    let grips: Vec<(f64, String)> =
        io_changes(&io_log).into_iter().filter(|(_, s, _)| s == "doGrip").map(|(t, _, v)| (t, v)).collect();
    assert_eq!(grips.len(), 6, "{grips:?}");
    for ((actual, value), (expected, expected_value)) in
        grips.iter().zip([(grip1, "1"), (release1, "0"), (grip2, "1"), (release2, "0")])
    {
        assert_eq!(value, expected_value);
        assert_near(*actual, expected, 0.002, "doGrip change");
    }
}

#[test]
fn the_turntable_example_welds_while_the_table_turns_half_a_turn() {
    let io_log = Path::new(env!("CARGO_TARGET_TMPDIR")).join("turntable_io.csv");
    let out = rapid(&["--io-log", io_log.to_str().expect("utf-8"), "examples/turntable"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "Seam welded\n");
    // The arc burns while the table turns 180° at 180 °/s with 0.15 s ramps: 1 + 0.15 s,
    // and the stop point's 0.05 s settle; the robot only follows the part.
    let arc: Vec<f64> = io_changes(&io_log).into_iter().filter(|(_, s, _)| s == "doArc").map(|(t, _, _)| t).collect();
    assert_eq!(arc.len(), 2, "{arc:?}");
    assert_near(arc[1] - arc[0], 1.2, 0.001, "arc time");
}

#[test]
fn the_positioner_cell_tacks_and_welds_as_the_tasks_take_turns() {
    let io_log = Path::new(env!("CARGO_TARGET_TMPDIR")).join("positioner_cell_io.csv");
    let out = rapid(&["--io-log", io_log.to_str().expect("utf-8"), "examples/positioner_cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // Worked by hand from the robot's home, 100 mm from the table's axis (IRB 120, table
    // 180 °/s with 0.15 s ramps, 0.05 s settle at each fine point):
    // side A, table at 0°: down 50 mm and up at v100 around a 0.2 s tack;
    let side_a = fine_move_l(50.0, 100.0) + 0.2 + fine_move_l(50.0, 100.0);
    // the table turns 180° while the robot stands (semi-coordinated): 1 + 0.15 + 0.05 s;
    let turn = 180.0 / 180.0 + 0.15 + 0.05;
    // side B: 200 mm across to above the turned edge, the tack at v200, 50 mm down at
    // v100 to the seam;
    let side_b = fine_move_l(200.0, 200.0) + fine_move_l(50.0, 200.0) + 0.2 + fine_move_l(50.0, 200.0);
    let to_seam = fine_move_l(50.0, 100.0);
    // the weld (synchronized): 50 mm along the rim at v20 alone 2.5 + 0.002 s, the table
    // back 180° alone 1.15 s: both take 2.502 s, + 0.05 s settle.
    let weld = fine_move_l(50.0, 20.0);
    let stdout = text(&out.stdout);
    let reported: f64 = stdout.trim().strip_prefix("Part done in ").expect("the report").parse().expect("a time");
    assert_near(reported, side_a + turn + side_b + to_seam + weld, 0.0015, "the cycle");
    let changes = io_changes(&io_log);
    let times =
        |signal: &str| -> Vec<f64> { changes.iter().filter(|(_, s, _)| s == signal).map(|(t, _, _)| *t).collect() };
    let (tack, arc) = (times("doTack"), times("doArc"));
    assert_eq!((tack.len(), arc.len()), (4, 2), "{changes:?}");
    // The second tack comes after the rest of side A, the turn and side B's approach.
    let between = fine_move_l(50.0, 100.0) + turn + fine_move_l(200.0, 200.0) + fine_move_l(50.0, 200.0);
    assert_near(tack[2] - tack[1], between, 0.0015, "from tack to tack");
    assert_near(arc[1] - arc[0], weld, 0.0015, "the weld");
}
