//! The speed override changed while the robot moves: the rest of the planned path is
//! walked at the new speed, its accelerations as planned. Worked by hand on a
//! Cartesian test robot (axes 1-3 are the TCP's x, y, z in mm), whose linear moves'
//! axis speeds are its TCP speed: 10 000 mm/s² of path acceleration, v1000.

use nalgebra::Isometry3;
use rapid_motion::plan::{retime, AccelLimits, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData};
use rapid_motion::{Joints, Kinematics, Pose};

/// A gantry: the flange is at (q1, q2, q3), never turned.
struct Gantry;

impl Kinematics for Gantry {
    fn forward(&self, q: &Joints) -> Pose {
        Isometry3::translation(q[0], q[1], q[2])
    }

    fn inverse(&self, flange: &Pose) -> Vec<Joints> {
        let t = flange.translation.vector;
        vec![[t.x, t.y, t.z, 0.0, 0.0, 0.0]]
    }

    fn limits(&self) -> [(f64, f64); 6] {
        [(-1e6, 1e6); 6]
    }

    fn max_speeds(&self) -> [f64; 6] {
        [1e5; 6]
    }
}

/// 10 000 mm/s², a settle time of 0.05 s at a stop point.
fn planner() -> Planner {
    Planner::new([0.0; 6], AccelLimits { tcp: 10_000.0, ori: 1e6, joint: [1e6; 6], settle: 0.05 })
}

fn move_to(x: f64, y: f64, zone: ZoneData) -> MoveRequest {
    MoveRequest {
        target: Target::Linear(Isometry3::translation(x, y, 0.0)),
        speed: SpeedData { v_tcp: 1000.0, v_ori: 500.0, v_leax: 5000.0, v_reax: 1000.0 },
        zone,
        tool: Pose::identity(),
        held_object: None,
        wobj: Pose::identity(),
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() < tol
}

/// Two stop points along x: 0 → 1000 → 1500 mm.
fn two_stops() -> (Planner, Vec<PlannedMove>) {
    let mut planner = planner();
    let mut moves = Vec::new();
    for x in [1000.0, 1500.0] {
        moves.extend(planner.push(&Gantry, &move_to(x, 0.0, ZoneData::FINE)).unwrap());
        moves.extend(planner.flush());
    }
    (planner, moves)
}

#[test]
fn half_the_speed_from_the_middle_of_a_move_slows_the_rest() {
    let (mut planner, mut moves) = two_stops();
    // As planned: 1000 mm with 0.1 s (50 mm) ramps and 900 mm of cruise at 1000 mm/s:
    // 1.1 s, then 0.05 s of settling; the second 500 mm take 0.6 s from 1.15 s.
    assert!(close(moves[0].zone_entry, 1.1, 1e-9) && close(moves[0].end, 1.15, 1e-9));
    assert!(close(moves[1].start, 1.15, 1e-9) && close(moves[1].end, 1.8, 1e-9));
    let map = retime(&mut moves, 0.5, 0.5);
    planner.retime(0.5, 0.5, &map);

    // At 0.5 s the robot is at 450 mm at 1000 mm/s. It brakes to 500 mm/s in 0.05 s
    // over (1000² − 500²)/20 000 = 37.5 mm, brakes to a stop at the end in 0.05 s over
    // 12.5 mm, and cruises the 500 mm between at 500 mm/s: 1 s, where at 1000 mm/s the
    // same 500 mm took 0.5 s. It stands at 1000 mm at 0.5 + 1.1 = 1.6 s, settled 1.65 s.
    let first = &moves[0];
    assert!(close(first.start, 0.0, 1e-12));
    assert!(close(first.zone_entry, 1.6, 1e-9) && close(first.end, 1.65, 1e-9), "{first:?}");
    let sample = first.sample(&Gantry, 1.05);
    assert!(close(sample.tcp.translation.vector.x, 450.0 + 37.5 + 250.0, 1e-6), "{sample:?}");
    assert!(close(sample.tcp_speed, 500.0, 1e-6));
    // Before the change nothing moved.
    assert!(close(first.sample(&Gantry, 0.3).tcp.translation.vector.x, 250.0, 1e-6));

    // The second move starts when the first now ends, its speed halved: 0.05 s and
    // 12.5 mm to 500 mm/s and as much to stop, 475 mm at 500 mm/s (0.95 s): 1.05 s,
    // and its settling.
    let second = &moves[1];
    assert!(close(second.start, 1.65, 1e-9), "{second:?}");
    assert!(close(second.end, 1.65 + 1.05 + 0.05, 1e-9), "{second:?}");

    // Old times map to new ones: where the robot was to be at 0.95 s (900 mm) it now
    // is at 0.55 + (900 − 487.5)/500 = 1.375 s; a settle end keeps its length; times
    // before the change stay; the planner's clock follows.
    assert!(close(map.map(0.95), 1.375, 1e-9));
    assert!(close(map.map(1.15), 1.65, 1e-9));
    assert!(close(map.map(1.8), 2.75, 1e-9));
    assert_eq!(map.map(0.25), 0.25);
    assert!(close(planner.time(), 2.75, 1e-9), "{}", planner.time());
}

#[test]
fn a_move_under_way_still_waiting_for_its_successor_is_slowed_where_it_is() {
    // A fly-by point with no successor yet: the robot moves as if it stopped there.
    let mut planner = planner();
    assert!(planner.push(&Gantry, &move_to(1000.0, 0.0, ZoneData::predefined("z10").unwrap())).unwrap().is_none());
    assert!(close(planner.pending_stop_time().unwrap(), 1.1, 1e-9));
    let map = retime(&mut [], 0.5, 0.5);
    planner.retime(0.5, 0.5, &map);
    // As in the stop-to-stop case: at 1000 mm at 1.6 s (no settling: a fly-by point
    // that had to stop).
    assert!(close(planner.pending_stop_time().unwrap(), 1.6, 1e-9));
    let (provisional, _) = planner.provisional().unwrap();
    assert!(close(provisional.sample(&Gantry, 1.05).tcp_speed, 500.0, 1e-6));
    let last = planner.flush().unwrap();
    assert!(close(last.end, 1.6, 1e-9) && last.corner_path_failure, "{last:?}");
    assert!(close(last.sample(&Gantry, 0.3).tcp.translation.vector.x, 250.0, 1e-6));
}

#[test]
fn a_corner_and_the_move_after_it_follow_the_new_speed_without_a_jump() {
    // 0 → 1000 mm along x through z50, then 500 mm along y to a stop point.
    let mut planner = planner();
    let z50 = ZoneData::predefined("z50").unwrap();
    assert!(planner.push(&Gantry, &move_to(1000.0, 0.0, z50)).unwrap().is_none());
    let mut moves: Vec<PlannedMove> =
        planner.push(&Gantry, &move_to(1000.0, 500.0, ZoneData::FINE)).unwrap().into_iter().collect();
    let map = retime(&mut moves, 0.5, 0.5);
    planner.retime(0.5, 0.5, &map);
    moves.extend(planner.flush());
    let (first, second) = (&moves[0], &moves[1]);
    assert!(close(second.start, first.end, 1e-12));
    // Cruising at half speed before the corner, and never above it after the change.
    assert!(close(first.sample(&Gantry, 1.0).tcp_speed, 500.0, 1e-6));
    for m in [first, second] {
        for s in m.samples(&Gantry, 0.004).filter(|s| s.time > 0.6) {
            assert!(s.tcp_speed <= 500.0 + 1e-6, "{s:?}");
        }
    }
    // The speed out of the corner is the speed the next move starts with.
    let out = first.sample(&Gantry, first.end).tcp_speed;
    let on = second.sample(&Gantry, second.start + 1e-9).tcp_speed;
    assert!(out > 0.0 && close(out, on, 1e-3), "{out} {on}");
    // The robot still ends where it was to.
    let end = second.sample(&Gantry, second.end).tcp.translation.vector;
    assert!(close(end.x, 1000.0, 1e-6) && close(end.y, 500.0, 1e-6));
}
