//! Throughput of the kinematics: forward kinematics, the eight-branch inverse, the
//! closest-to-seed inverse (ConfJ\Off) and the confdata inverse (ConfJ\On), on random
//! joint sets within the limits of a built-in model. Prints the median of several runs.
//!
//! Run with `bench/motion/run.sh [MODEL] [RUNS]`, or
//! `cargo bench -p rapid-motion --bench ik -- [MODEL] [RUNS]`.

#![allow(clippy::print_stdout, clippy::print_stderr)]

use std::hint::black_box;
use std::time::Instant;

use rapid_motion::{confdata_of, find_model, inverse_conf, ConfData, ConfMatch, Joints, Kinematics, Pose};

const SAMPLES: usize = 200_000;

fn main() {
    // `cargo bench` passes `--bench`; skip flags.
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let name = args.first().map_or("IRB 120", String::as_str);
    let runs: usize = args.get(1).and_then(|r| r.parse().ok()).unwrap_or(5).clamp(1, 50);
    let Some(model) = find_model(name) else {
        eprintln!("no built-in model named {name}");
        std::process::exit(2);
    };
    let kin = model.kinematics();

    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let joints: Vec<Joints> = (0..SAMPLES).map(|_| random_joints(&mut state, &kin.limits())).collect();
    let poses: Vec<Pose> = joints.iter().map(|j| kin.forward(j)).collect();
    let confs: Vec<ConfData> = joints.iter().map(|j| confdata_of(&kin, j)).collect();

    let recovered = joints
        .iter()
        .zip(&poses)
        .filter(|(j, p)| {
            kin.inverse_near(p, j).is_ok_and(|s| s.iter().zip(j.iter()).all(|(a, b)| (a - b).abs() < 1e-6))
        })
        .count();
    println!("model {}, {SAMPLES} random joint sets within limits, median of {runs} runs", model.name);
    println!("round trip: {recovered} of {SAMPLES} recovered within 1e-6 deg");

    let fk = median(runs, || {
        for j in &joints {
            black_box(kin.forward(black_box(j)));
        }
    });
    let branches = median(runs, || {
        for p in &poses {
            black_box(kin.branches(black_box(p), None));
        }
    });
    let near = median(runs, || {
        for (p, j) in poses.iter().zip(&joints) {
            let _ = black_box(kin.inverse_near(black_box(p), j));
        }
    });
    let conf = median(runs, || {
        for (p, c) in poses.iter().zip(&confs) {
            let _ = black_box(inverse_conf(&kin, black_box(p), c, &[0.0; 6], ConfMatch::Compliant));
        }
    });
    report("FK", fk);
    report("IK, all 8 branches", branches);
    report("IK, closest to seed (ConfJ\\Off)", near);
    report("IK, by confdata (ConfJ\\On)", conf);
}

/// The median wall time in seconds of `runs` runs of `f` over all samples.
fn median(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn report(what: &str, seconds: f64) {
    let per_second = SAMPLES as f64 / seconds;
    println!("{what:<34} {per_second:>12.0} /s   {:>7.3} us each", 1e6 / per_second);
}

fn random_joints(state: &mut u64, limits: &[(f64, f64); 6]) -> Joints {
    std::array::from_fn(|i| {
        *state ^= *state >> 12;
        *state ^= *state << 25;
        *state ^= *state >> 27;
        let unit = (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64;
        limits[i].0 + (limits[i].1 - limits[i].0) * unit
    })
}
