//! SingArea\Wrist (manual §2.2.2): near a singular point a linear move interpolates the
//! wrist axes axis by axis while the TCP keeps its straight line; the orientation
//! differs somewhat from the programmed one on the way.

use nalgebra::{Isometry3, Translation3, Vector3};
use rapid_motion::plan::{AccelLimits, MotionSettings, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData};
use rapid_motion::{default_model, Joints, Kinematics, MotionError, Opw, Pose};

/// The IRB 120, the start [0,0,0,45,3,0] (axis 5 near the wrist singularity), and a
/// MoveL 60 mm straight down at v100 keeping the start's orientation, `fine`.
fn setup() -> (Opw, Joints, MoveRequest) {
    let kin = default_model().kinematics();
    let start = [0.0, 0.0, 0.0, 45.0, 3.0, 0.0];
    let from = kin.forward(&start);
    let to = Isometry3::from_parts(
        Translation3::from(from.translation.vector - Vector3::new(0.0, 0.0, 60.0)),
        from.rotation,
    );
    let speed = SpeedData { v_tcp: 100.0, v_ori: 500.0, v_leax: 5000.0, v_reax: 1000.0 };
    let request = MoveRequest {
        target: Target::Linear(to),
        speed,
        zone: ZoneData::FINE,
        tool: Pose::identity(),
        held_object: None,
        wobj: Pose::identity(),
    };
    (kin, start, request)
}

fn plan(kin: &Opw, start: Joints, request: &MoveRequest, wrist: bool) -> Result<PlannedMove, MotionError> {
    let accel = AccelLimits { tcp: 10_000.0, ori: 1e6, joint: [1e6; 6], settle: 0.0 };
    let mut planner = Planner::new(start, accel);
    planner.set_settings(MotionSettings { sing_wrist: wrist, ..MotionSettings::default() });
    let first = planner.push(kin, request)?;
    Ok(first.or_else(|| planner.flush()).expect("the move"))
}

#[test]
fn with_sing_area_off_the_move_cannot_keep_its_orientation() {
    // Keeping the orientation, axis 4 would pass its 160° limit (166.76° at the end,
    // tests/hand/path_joint_limit.py).
    let (kin, start, request) = setup();
    assert_eq!(plan(&kin, start, &request, false).err(), Some(MotionError::JointLimit { axis: 4 }));
}

#[test]
fn with_sing_area_wrist_the_wrist_goes_straight_in_joint_space() {
    // The end's solution within the ranges nearest the start is the other wrist
    // branch of [0, -1.66, 12.84, 166.76, 9.30, -121.97]: axes 4, 6 half a turn
    // round, axis 5 negated: [0, -1.66, 12.84, -13.24, -9.30, 58.03]. The wrist axes
    // go straight from [45, 3, 0] to [-13.24, -9.30, 58.03]; at most 58° in the move's
    // 0.6 s, far below their 320 and 420 °/s, so the TCP keeps v100:
    // 60/100 + 100/10000 = 0.61 s.
    let (kin, start, request) = setup();
    let planned = plan(&kin, start, &request, true).expect("the move is made");
    assert!((planned.duration() - 0.61).abs() < 1e-6, "{}", planned.duration());
    let expected_end = [0.0, -1.66, 12.84, -13.24, -9.30, 58.03];
    assert!(planned.end_joints.iter().zip(expected_end).all(|(a, b)| (a - b).abs() < 0.01), "{:?}", planned.end_joints);
    // Half way down (the trapezoid is symmetric: at half its time) the wrist is half
    // way, and the TCP is on the line, 30 mm below the start.
    let mid = planned.sample(&kin, planned.start + planned.duration() / 2.0);
    let half = [(45.0 - 13.24) / 2.0, (3.0 - 9.30) / 2.0, 58.03 / 2.0];
    assert!(mid.joints[3..].iter().zip(half).all(|(a, b)| (a - b).abs() < 0.01), "{:?}", mid.joints);
    let from = kin.forward(&start).translation.vector;
    let below = mid.tcp.translation.vector - (from - Vector3::new(0.0, 0.0, 30.0));
    assert!(below.norm() < 1e-6, "{below}");
    // The orientation there is not the programmed one (§2.2.2: it differs somewhat);
    // at the end it is.
    assert!(mid.tcp.rotation.angle_to(&kin.forward(&start).rotation) > 1f64.to_radians());
    let end = planned.sample(&kin, planned.end);
    assert!(end.tcp.rotation.angle_to(&kin.forward(&start).rotation) < 1e-6);
}

#[test]
fn far_from_singular_points_sing_area_wrist_changes_little() {
    // A move far from singular points ends at the same joints either way, and takes
    // the same time (the TCP's √(36² + 48²) = 60 mm at v100).
    let kin = default_model().kinematics();
    let start = [10.0, 20.0, 10.0, 20.0, 60.0, 30.0];
    let from = kin.forward(&start);
    let to = Isometry3::from_parts(
        Translation3::from(from.translation.vector - Vector3::new(0.0, 36.0, 48.0)),
        from.rotation,
    );
    let request = MoveRequest { target: Target::Linear(to), ..setup().2 };
    let (off, wrist) = (plan(&kin, start, &request, false).unwrap(), plan(&kin, start, &request, true).unwrap());
    assert!(off.end_joints.iter().zip(wrist.end_joints).all(|(a, b)| (a - b).abs() < 1e-6));
    assert!((off.duration() - 0.61).abs() < 1e-6 && (wrist.duration() - 0.61).abs() < 1e-6);
}

#[test]
fn corners_between_wrist_moves_blend_the_tcp_as_any_linear_corner() {
    // Two 60 mm moves at a right angle through a z10 corner, far from singular points:
    // with SingArea\Wrist the TCP takes the same parabola (the corner is a TCP corner,
    // the wrist axes going straight across it), so the moves take as long as with \Off:
    // 2 · 60/100 + 0.01 s of ramp, the corner 2·10/100 = 0.2 s in place of 20 mm of lines.
    let kin = default_model().kinematics();
    let start = [10.0, 20.0, 10.0, 20.0, 60.0, 30.0];
    let from = kin.forward(&start);
    let at = |dy: f64, dz: f64| {
        let p = from.translation.vector + Vector3::new(0.0, dy, dz);
        Isometry3::from_parts(Translation3::from(p), from.rotation)
    };
    let z10 = ZoneData::predefined("z10").unwrap();
    let first = MoveRequest { target: Target::Linear(at(-60.0, 0.0)), zone: z10, ..setup().2 };
    let second = MoveRequest { target: Target::Linear(at(-60.0, -60.0)), ..setup().2 };
    let both = |wrist: bool| {
        let accel = AccelLimits { tcp: 10_000.0, ori: 1e6, joint: [1e6; 6], settle: 0.0 };
        let mut planner = Planner::new(start, accel);
        planner.set_settings(MotionSettings { sing_wrist: wrist, ..MotionSettings::default() });
        let mut moves: Vec<PlannedMove> = planner.push(&kin, &first).unwrap().into_iter().collect();
        moves.extend(planner.push(&kin, &second).unwrap());
        moves.extend(planner.flush());
        moves
    };
    let (off, wrist) = (both(false), both(true));
    assert_eq!(wrist[0].corner_kind(), Some(rapid_motion::plan::CornerKind::Tcp));
    let total = |m: &[PlannedMove]| m.last().unwrap().end - m[0].start;
    assert!((total(&off) - 1.21).abs() < 1e-6, "{}", total(&off));
    assert!((total(&wrist) - 1.21).abs() < 1e-6, "{}", total(&wrist));
    // The middle of the corner is at the same place either way.
    let mid = |m: &[PlannedMove]| m[0].sample(&kin, m[0].zone_entry + m[0].corner_time / 2.0).tcp.translation.vector;
    assert!((mid(&off) - mid(&wrist)).norm() < 1e-6, "{} vs {}", mid(&off), mid(&wrist));
}
