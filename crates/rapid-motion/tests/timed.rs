//! `\T` (a move's time instead of its speed) and `\Inpos` stop times, worked by hand
//! on a Cartesian test robot: axes 1-3 are the TCP's x, y, z in mm, axes 4-6 fixed
//! angles, so a linear move's axis speeds are its TCP speed.

use nalgebra::Isometry3;
use rapid_motion::plan::{AccelLimits, MotionSettings, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData};
use rapid_motion::{Joints, Kinematics, MotionError, Pose};

/// A gantry: the flange is at (q1, q2, q3), never turned.
struct Gantry {
    speeds: [f64; 6],
}

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
        self.speeds
    }
}

const FAST: Gantry = Gantry { speeds: [1e5; 6] };

/// TCP acceleration 10 000 mm/s², no settle time unless asked.
fn accel(settle: f64) -> AccelLimits {
    AccelLimits { tcp: 10_000.0, ori: 1e6, joint: [1e6; 6], settle }
}

fn v1000() -> SpeedData {
    SpeedData { v_tcp: 1000.0, v_ori: 500.0, v_leax: 5000.0, v_reax: 1000.0 }
}

/// One MoveL along x to `x` (fine) with these settings, planned from x = 0.
fn one_move(kin: &Gantry, acc: AccelLimits, x: f64, settings: MotionSettings) -> Result<PlannedMove, MotionError> {
    let mut planner = Planner::new([0.0; 6], acc);
    planner.set_settings(settings);
    let request = MoveRequest {
        target: Target::Linear(Isometry3::translation(x, 0.0, 0.0)),
        speed: v1000(),
        zone: ZoneData::FINE,
        tool: Pose::identity(),
        held_object: None,
        wobj: Pose::identity(),
    };
    assert!(planner.push(kin, &request)?.is_none());
    Ok(planner.flush().expect("the move"))
}

fn timed(t: f64) -> MotionSettings {
    MotionSettings { move_time: Some(t), ..MotionSettings::default() }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn t_sets_the_time_of_a_long_move() {
    // 1000 mm in 5 s, a = 10 000: T = L/v + v/a gives v² - aT·v + aL = 0, the smaller
    // root v = (50 000 - √(2.5e9 - 4e7)) / 2 = 200.80… mm/s; the move takes 5 s, far
    // slower than v1000 would (1.1 s).
    let planned = one_move(&FAST, accel(0.0), 1000.0, timed(5.0)).expect("plan");
    assert!(close(planned.duration(), 5.0), "{}", planned.duration());
    let v = (50_000.0 - (2.5e9f64 - 4e7).sqrt()) / 2.0;
    assert!((planned.sample(&FAST, 2.5).tcp_speed - v).abs() < 1e-6);
}

#[test]
fn t_can_make_a_move_faster_than_its_speeddata() {
    // 1000 mm in 0.6 s: v = (6000 - √(3.6e7 - 4e7)) / 2 has no root (3.6e7 < 4e7), so
    // the fastest triangle: peak √(aL) = 3162.3 mm/s, T = 2·√(L/a) = 0.632 s.
    let planned = one_move(&FAST, accel(0.0), 1000.0, timed(0.6)).expect("plan");
    assert!(close(planned.duration(), 2.0 * (1000.0f64 / 10_000.0).sqrt()), "{}", planned.duration());
    // 0.7 s is feasible: v = (7000 - √(4.9e7 - 4e7)) / 2 = 2000 mm/s, faster than v1000.
    let planned = one_move(&FAST, accel(0.0), 1000.0, timed(0.7)).expect("plan");
    assert!(close(planned.duration(), 0.7), "{}", planned.duration());
}

#[test]
fn t_stays_within_the_axis_limits() {
    // Axis 1 at most 500 mm/s: 1000 mm in 1 s would need 1127 mm/s; the axis caps it
    // at 500: T = 1000/500 + 500/10 000 = 2.05 s.
    let slow = Gantry { speeds: [500.0, 1e5, 1e5, 1e5, 1e5, 1e5] };
    let planned = one_move(&slow, accel(0.0), 1000.0, timed(1.0)).expect("plan");
    assert!(close(planned.duration(), 2.05), "{}", planned.duration());
}

#[test]
fn t_is_stretched_by_the_speed_override() {
    // VelSet 50 %: the move takes 2 × 2 s.
    let settings = MotionSettings { vel_override: 50.0, ..timed(2.0) };
    let planned = one_move(&FAST, accel(0.0), 1000.0, settings).expect("plan");
    assert!(close(planned.duration(), 4.0), "{}", planned.duration());
}

#[test]
fn t_must_be_a_positive_time() {
    for t in [0.0, -1.0, f64::NAN] {
        assert!(matches!(one_move(&FAST, accel(0.0), 1000.0, timed(t)), Err(MotionError::InvalidData(_))));
    }
}

#[test]
fn stop_time_replaces_the_settle_time() {
    // v1000 over 1000 mm: 1.1 s of motion, then 0.5 s standing (instead of 0.05).
    let settings = MotionSettings { stop_time: Some(0.5), ..MotionSettings::default() };
    let planned = one_move(&FAST, accel(0.05), 1000.0, settings).expect("plan");
    assert!(close(planned.zone_entry, 1.1) && close(planned.end, 1.6), "{planned:?}");
}
