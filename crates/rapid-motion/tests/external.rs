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
        wobj: Pose::identity(),
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

/// The turntable of these tests (180 °/s, full speed in 0.15 s: 1200 °/s²) turning
/// while the track stands at `track_at`.
fn turntable(track_at: f64, from: f64, to: f64) -> ExternalMove {
    let mut ext = ExternalMove { from: [0.0; 6], to: [0.0; 6], max_speed: [0.0; 6], acc: [0.0; 6], linear: [false; 6] };
    (ext.from[0], ext.to[0]) = (track_at, track_at);
    (ext.max_speed[0], ext.acc[0], ext.linear[0]) = (1000.0, 1000.0 / 0.15, true);
    (ext.from[1], ext.to[1], ext.max_speed[1], ext.acc[1]) = (from, to, 180.0, 180.0 / 0.15);
    ext
}

/// Moves of the external axes alone (the arm stands at 0) through `legs`, each with
/// its zone; the last one ends the queue.
fn axes_only(legs: &[(ExternalMove, &str)]) -> Vec<PlannedMove> {
    let model = default_model();
    let kin = model.kinematics();
    let mut planner = Planner::new([0.0; 6], AccelLimits::nominal(&model.max_speeds));
    planner.set_eax(Some(legs[0].0.from));
    let mut moves = Vec::new();
    for (ext, zone) in legs {
        moves.extend(planner.push_with(&kin, &request([0.0; 6], v1000(), zone), Some(ext)).unwrap());
    }
    moves.extend(planner.flush());
    moves
}

#[test]
fn moves_of_the_axes_alone_blend_in_their_zone() {
    // 0 → 1000 → 2000 mm with z100 between (zone_leax 150 mm, under half of either
    // move): one straight corner from 850 to 1150 mm walked at full speed, so the two
    // moves take what one of 2000 mm takes: 2000/1000 + 0.15 = 2.15 s, + 0.05 s settle.
    let moves = axes_only(&[(track(0.0, 1000.0), "z100"), (track(1000.0, 2000.0), "fine")]);
    assert_eq!(moves.len(), 2);
    assert!(close(moves[1].end, 2.15 + SETTLE, 1e-6), "end {}", moves[1].end);
    // The corner starts at 850 mm: 0.15 s of ramp (75 mm) and 775 mm at full speed.
    assert!(close(moves[0].zone_entry, 0.925, 1e-6), "entry {}", moves[0].zone_entry);
    assert!(close(moves[0].corner_time, 0.3, 1e-6));
    assert!(close(moves[0].eax_at(1.075).unwrap()[0], 1000.0, 1e-6));
    let kin = default_model().kinematics();
    let in_corner = moves[0].sample(&kin, 1.0);
    assert_eq!((in_corner.joints, in_corner.tcp_speed), ([0.0; 6], 0.0), "the arm stands");
}

#[test]
fn a_corner_from_the_track_to_the_turntable_is_a_parabola() {
    // The track 0 → 1000 mm, then the turntable 0 → 90°, z100 between: the corner runs
    // from 850 mm (zone_leax 150) to 15° (zone_reax 15), with the point (1000 mm, 0°)
    // as its control point. Weighted by the axes' speeds (1/1000, 1/180) the legs are
    // 0.15 and 0.083 at 90°; both moves allow 6.67 s⁻² there, so the corner's speed is
    // √(6.67 · 0.0833 / sin 45°) = 0.886: the track enters at 886 mm/s and the table
    // leaves at 159.5 °/s. Parameter rates 2.955 and 5.318 s⁻¹: the corner takes
    // 2 / 8.273 = 0.2418 s. Before it: a 0.15 s ramp, 758.9 mm at 1000 mm/s, 0.017 s
    // down to 886 mm/s: 0.9260 s. After it: 0.017 s up to 180 °/s, 58.6° at full speed,
    // a 0.15 s ramp down: 0.4926 s. In all 1.6604 s, + 0.05 s settle.
    let moves = axes_only(&[(track(0.0, 1000.0), "z100"), (turntable(1000.0, 0.0, 90.0), "fine")]);
    assert!(close(moves[0].zone_entry, 0.9260, 1e-3), "entry {}", moves[0].zone_entry);
    assert!(close(moves[0].corner_time, 0.2418, 1e-3), "corner {}", moves[0].corner_time);
    assert!(close(moves[1].end, 1.6604 + SETTLE, 1e-3), "end {}", moves[1].end);
    // Half way along the parabola (a + 2p + b)/4 = (962.5 mm, 3.75°), reached at
    // 1.0638 s (the parameter's rate grows linearly from 2.955 to 5.318 s⁻¹).
    let mid = moves[0].eax_at(1.0638).unwrap();
    assert!(close(mid[0], 962.5, 0.1) && close(mid[1], 3.75, 0.01), "{mid:?}");
}

#[test]
fn no_corner_between_a_move_of_the_axes_alone_and_one_of_the_arm() {
    // §2.2.3: the track's move and a move of axis 6 meet at a stop point, z100 or not
    // (no settle, it is no `fine` point): 1.15 s, then the arm's triangle 0.245 s.
    let model = default_model();
    let kin = model.kinematics();
    let mut planner = Planner::new([0.0; 6], AccelLimits::nominal(&model.max_speeds));
    planner.set_eax(Some([0.0; 6]));
    let arm = [0.0, 0.0, 0.0, 0.0, 0.0, 42.0];
    let mut moves = Vec::new();
    moves.extend(planner.push_with(&kin, &request([0.0; 6], v1000(), "z100"), Some(&track(0.0, 1000.0))).unwrap());
    moves.extend(planner.push_with(&kin, &request(arm, v1000(), "fine"), Some(&track(1000.0, 1000.0))).unwrap());
    moves.extend(planner.flush());
    assert_eq!(moves[0].corner_time, 0.0);
    assert!(close(moves[0].end, 1.15, 1e-6), "end {}", moves[0].end);
    let triangle = 2.0 * (42.0f64 / 2800.0).sqrt();
    assert!(close(moves[1].end, 1.15 + triangle + SETTLE, 1e-6), "end {}", moves[1].end);
}
