//! Planner throughput: 100,000 MoveL (fly-by z10 along a zigzag, a `fine` point
//! every 50 moves) planned and sampled at 4 ms, on a gantry test robot whose IK
//! costs next to nothing, so the figures are the planner's own cost. IK calls
//! are counted so the cost of a real solver can be added per call.
//!
//! Run: `cargo run --release -p rapid-motion --example plan_bench`

#![allow(clippy::print_stdout)]

use std::cell::Cell;
use std::time::Instant;

use rapid_motion::plan::{AccelLimits, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData, DEFAULT_STEP};
use rapid_motion::pose::pose;
use rapid_motion::{Joints, Kinematics, Pose};

/// Axes 1-3 are x, y, z in mm; the wrist stays put. Counts IK calls.
struct Gantry {
    ik_calls: Cell<u64>,
}

impl Kinematics for Gantry {
    fn forward(&self, q: &Joints) -> Pose {
        Pose::translation(q[0], q[1], q[2])
    }

    fn inverse(&self, flange: &Pose) -> Vec<Joints> {
        self.ik_calls.set(self.ik_calls.get() + 1);
        let t = flange.translation.vector;
        vec![[t.x, t.y, t.z, 0.0, 0.0, 0.0]]
    }

    fn limits(&self) -> [(f64, f64); 6] {
        [(-1e5, 1e5); 6]
    }

    fn max_speeds(&self) -> [f64; 6] {
        [2000.0, 2000.0, 2000.0, 320.0, 320.0, 420.0]
    }
}

const MOVES: usize = 100_000;

fn main() {
    let robot = Gantry { ik_calls: Cell::new(0) };
    let (v1000, z10) = (SpeedData::predefined("v1000").unwrap_or(SpeedData::VMAX), ZoneData::fly_by(10.0));
    let requests: Vec<MoveRequest> = (0..MOVES)
        .map(|i| {
            let x = 400.0 + 50.0 * (i % 20) as f64;
            let y = if i % 2 == 0 { -150.0 } else { 150.0 };
            let zone = if i % 50 == 49 { ZoneData::FINE } else { z10 };
            let target = Target::Linear(pose([x, y, 500.0], [1.0, 0.0, 0.0, 0.0]));
            MoveRequest {
                target,
                speed: v1000,
                zone,
                tool: Pose::identity(),
                held_object: None,
                wobj: Pose::identity(),
            }
        })
        .collect();

    let started = Instant::now();
    let mut planner = Planner::new([400.0, 0.0, 500.0, 0.0, 0.0, 0.0], AccelLimits::nominal(&robot.max_speeds()));
    let mut planned: Vec<PlannedMove> = Vec::with_capacity(MOVES);
    for request in &requests {
        match planner.push(&robot, request) {
            Ok(done) => planned.extend(done),
            Err(e) => return println!("planning failed: {e}"),
        }
    }
    planned.extend(planner.flush());
    let plan_wall = started.elapsed().as_secs_f64();
    let plan_ik = robot.ik_calls.get();

    let started = Instant::now();
    let mut samples = 0u64;
    let mut checksum = 0.0;
    for m in &planned {
        for s in m.samples(&robot, DEFAULT_STEP) {
            samples += 1;
            checksum += s.tcp_speed;
        }
    }
    let sample_wall = started.elapsed().as_secs_f64();
    let sample_ik = robot.ik_calls.get() - plan_ik;

    let simulated = planned.last().map_or(0.0, |m| m.end);
    let wall = plan_wall + sample_wall;
    println!("moves planned:        {}", planned.len());
    println!("simulated time:       {simulated:.1} s");
    println!("plan wall time:       {plan_wall:.3} s ({:.0} moves/s, {plan_ik} IK calls)", MOVES as f64 / plan_wall);
    println!("sample wall time:     {sample_wall:.3} s ({samples} samples at 4 ms, {sample_ik} IK calls)");
    println!("simulated / wall:     {:.0}x (planner only, test-robot IK)", simulated / wall);
    println!("IK calls per move:    {:.1}", (plan_ik + sample_ik) as f64 / MOVES as f64);
    println!("mean TCP speed:       {:.1} mm/s", checksum / samples.max(1) as f64);
}
