//! External axes in the planner, worked by hand on the IRB 120 (axis 6: 420 °/s,
//! reaching full speed in 0.15 s) and a linear external axis of 1000 mm/s that also
//! reaches full speed in 0.15 s (6666.7 mm/s²). A stop point adds 0.05 s of settle.

use rapid_motion::external::ExternalMove;
use rapid_motion::plan::{AccelLimits, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData};
use rapid_motion::{default_model, Joints, MotionError, Pose};

const SETTLE: f64 = 0.05;

fn track(from: f64, to: f64) -> ExternalMove {
    let mut ext = ExternalMove { from: [0.0; 6], to: [0.0; 6], max_speed: [0.0; 6], acc: [0.0; 6], linear: [false; 6] };
    (ext.from[0], ext.to[0], ext.max_speed[0], ext.acc[0], ext.linear[0]) = (from, to, 1000.0, 1000.0 / 0.15, true);
    ext
}

fn request(joints: Joints, speed: SpeedData, zone: &str) -> MoveRequest {
    MoveRequest {
        target: Target::Joints(joints),
        speed,
        zone: ZoneData::predefined(zone).unwrap(),
        tool: Pose::identity(),
        held_object: None,
    }
}

fn v1000() -> SpeedData {
    SpeedData::predefined("v1000").unwrap()
}

/// One stop-point move from the calibration position with the track's move.
fn plan_one(joints: Joints, speed: SpeedData, ext: &ExternalMove) -> Result<PlannedMove, MotionError> {
    let model = default_model();
    let kin = model.kinematics();
    let mut planner = Planner::new([0.0; 6], AccelLimits::nominal(&model.max_speeds));
    planner.set_eax(Some(ext.from));
    assert!(planner.push_with(&kin, &request(joints, speed, "fine"), Some(ext))?.is_none());
    Ok(planner.flush().expect("the move is final"))
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn the_track_alone_moves_on_its_own_trapezoid() {
    // 1000 mm at 1000 mm/s with 0.15 s ramps: 1000/1000 + 0.15 = 1.15 s.
    let planned = plan_one([0.0; 6], v1000(), &track(0.0, 1000.0)).unwrap();
    assert!(close(planned.end, 1.15 + SETTLE, 1e-6), "end {}", planned.end);
    // The trapezoid is symmetric: half way in time is half way in distance.
    assert!(close(planned.eax_at(0.575).unwrap()[0], 500.0, 1e-6));
    // After 0.15 s of acceleration: a·t²/2 = 6666.7 · 0.0225 / 2 = 75 mm.
    assert!(close(planned.eax_at(0.15).unwrap()[0], 75.0, 1e-6));
    assert!(close(planned.eax_end().unwrap()[0], 1000.0, 1e-9));
    let kin = default_model().kinematics();
    assert_eq!(planned.sample(&kin, 0.5).joints, [0.0; 6], "the arm stands still");
}

#[test]
fn a_slow_track_slows_the_arm_so_both_arrive_together() {
    // Axis 6 alone: 42° at 420 °/s, a triangle profile 2·√(42/2800) = 0.245 s. The
    // track needs 1.15 s, so the arm takes that long too.
    let arm = [0.0, 0.0, 0.0, 0.0, 0.0, 42.0];
    let planned = plan_one(arm, v1000(), &track(0.0, 1000.0)).unwrap();
    assert!(close(planned.end, 1.15 + SETTLE, 1e-6), "end {}", planned.end);
    let kin = default_model().kinematics();
    assert!(close(planned.sample(&kin, 0.575).joints[5], 21.0, 1e-6));
    assert!(close(planned.eax_at(0.575).unwrap()[0], 500.0, 1e-6));
}

#[test]
fn a_short_track_move_follows_the_arm() {
    // 10 mm of track within the arm's 0.245 s: the arm sets the pace.
    let arm = [0.0, 0.0, 0.0, 0.0, 0.0, 42.0];
    let planned = plan_one(arm, v1000(), &track(0.0, 10.0)).unwrap();
    let triangle = 2.0 * (42.0f64 / 2800.0).sqrt();
    assert!(close(planned.end, triangle + SETTLE, 1e-6), "end {}", planned.end);
    assert!(close(planned.eax_at(triangle / 2.0).unwrap()[0], 5.0, 1e-6));
}

#[test]
fn v_leax_bounds_a_linear_axis() {
    // v_leax 200 mm/s: 1000/200 + 200/6666.7 = 5.03 s.
    let speed = SpeedData { v_tcp: 100.0, v_ori: 500.0, v_leax: 200.0, v_reax: 1000.0 };
    let planned = plan_one([0.0; 6], speed, &track(0.0, 1000.0)).unwrap();
    assert!(close(planned.end, 5.03 + SETTLE, 1e-6), "end {}", planned.end);
}

#[test]
fn a_zero_axis_speed_is_refused() {
    let speed = SpeedData { v_tcp: 100.0, v_ori: 500.0, v_leax: 0.0, v_reax: 1000.0 };
    let err = plan_one([0.0; 6], speed, &track(0.0, 1000.0)).unwrap_err();
    assert!(matches!(err, MotionError::InvalidData(_)));
}

#[test]
fn the_track_moves_smoothly_through_fly_by_corners() {
    let model = default_model();
    let kin = model.kinematics();
    let mut planner = Planner::new([0.0; 6], AccelLimits::nominal(&model.max_speeds));
    planner.set_eax(Some([0.0; 6]));
    let legs = [([30.0, 0.0, 0.0, 0.0, 0.0, 0.0], 300.0), ([30.0, 20.0, 0.0, 0.0, 0.0, 0.0], 600.0)];
    let mut moves = Vec::new();
    let mut from = 0.0;
    for (i, (arm, to)) in legs.iter().enumerate() {
        let zone = if i == 0 { "z50" } else { "fine" };
        moves.extend(planner.push_with(&kin, &request(*arm, v1000(), zone), Some(&track(from, *to))).unwrap());
        from = *to;
    }
    moves.extend(planner.flush());
    assert_eq!(moves.len(), 2);
    assert!(moves[0].corner_time > 0.0, "the first point is flown by");
    assert_eq!(planner.end_eax(), Some([600.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
    // Sampled every millisecond, the track never jumps: at 1000 mm/s it moves at most
    // 1 mm per step (a little more is allowed inside the corner's straight blend).
    let mut last = 0.0;
    let end = moves[1].end;
    let mut t = 0.0;
    while t <= end {
        let m = if t <= moves[0].end { &moves[0] } else { &moves[1] };
        let x = m.eax_at(t).unwrap()[0];
        assert!((x - last).abs() <= 1.5, "jump from {last} to {x} at {t}");
        last = x;
        t += 0.001;
    }
    assert!(close(last, 600.0, 1e-6));
}
