//! Planner timing and geometry, worked by hand on a Cartesian test robot whose
//! inverse kinematics is trivial: axes 1-3 are the TCP's x, y, z in mm, axes
//! 4-6 its ZYX Euler angles in degrees.

use std::f64::consts::{FRAC_1_SQRT_2, PI};

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use rapid_motion::plan::{
    AccelLimits, CornerKind, MotionSettings, MoveRequest, PlannedMove, Planner, SpeedData, Target, ZoneData,
    DEFAULT_STEP,
};
use rapid_motion::{Joints, Kinematics, MotionError, Pose};

/// A gantry with a spherical wrist at the TCP.
struct Gantry {
    speeds: [f64; 6],
}

impl Kinematics for Gantry {
    fn forward(&self, q: &Joints) -> Pose {
        let r = UnitQuaternion::from_euler_angles(q[5].to_radians(), q[4].to_radians(), q[3].to_radians());
        Isometry3::from_parts(Translation3::new(q[0], q[1], q[2]), r)
    }

    fn inverse(&self, flange: &Pose) -> Vec<Joints> {
        let t = flange.translation.vector;
        let (x, y, z) = flange.rotation.euler_angles();
        let q = [t.x, t.y, t.z, z.to_degrees(), y.to_degrees(), x.to_degrees()];
        let inside = q.iter().zip(self.limits()).all(|(v, (lo, hi))| (lo..=hi).contains(v));
        if inside {
            vec![q]
        } else {
            Vec::new()
        }
    }

    fn limits(&self) -> [(f64, f64); 6] {
        [(-1e6, 1e6), (-1e6, 1e6), (-1e6, 1e6), (-180.0, 180.0), (-90.0, 90.0), (-180.0, 180.0)]
    }

    fn max_speeds(&self) -> [f64; 6] {
        self.speeds
    }
}

const FAST: Gantry = Gantry { speeds: [1e5; 6] };

fn accel(tcp: f64) -> AccelLimits {
    AccelLimits { tcp, ori: 1e6, joint: [1e6; 6], settle: 0.0 }
}

fn at(x: f64, y: f64, z: f64) -> Pose {
    Isometry3::translation(x, y, z)
}

fn turned(x: f64, y: f64, z: f64, deg_about_z: f64) -> Pose {
    Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(0.0, 0.0, deg_about_z.to_radians()),
    )
}

fn speed(v_tcp: f64, v_ori: f64) -> SpeedData {
    SpeedData { v_tcp, v_ori, v_leax: 5000.0, v_reax: 1000.0 }
}

fn linear(to: Pose, v: f64, zone: ZoneData) -> MoveRequest {
    MoveRequest {
        target: Target::Linear(to),
        speed: speed(v, 500.0),
        zone,
        tool: Pose::identity(),
        held_object: None,
        wobj: Pose::identity(),
    }
}

/// Plans `moves` in order and flushes.
fn plan_all<K: Kinematics>(kin: &K, acc: AccelLimits, moves: &[MoveRequest]) -> Vec<PlannedMove> {
    let mut planner = Planner::new([0.0; 6], acc);
    let mut planned: Vec<PlannedMove> = moves.iter().filter_map(|m| planner.push(kin, m).unwrap()).collect();
    planned.extend(planner.flush());
    planned
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn long_move_is_l_over_v_plus_v_over_a() {
    let planned = plan_all(&FAST, accel(10_000.0), &[linear(at(1000.0, 0.0, 0.0), 1000.0, ZoneData::FINE)]);
    // T = L/v + v/a = 1000/1000 + 1000/10000.
    assert!(close(planned[0].duration(), 1.1, 1e-9));
    let half = planned[0].sample(&FAST, 0.55);
    assert!(close(half.tcp.translation.x, 500.0, 1e-6) && close(half.tcp_speed, 1000.0, 1e-6));
    assert!(close(half.joints[0], 500.0, 1e-6));
}

#[test]
fn short_move_is_two_root_l_over_a() {
    let planned = plan_all(&FAST, accel(10_000.0), &[linear(at(10.0, 0.0, 0.0), 1000.0, ZoneData::FINE)]);
    // L = 10 mm < v²/a = 100 mm: T = 2·√(L/a).
    assert!(close(planned[0].duration(), 2.0 * (10.0f64 / 10_000.0).sqrt(), 1e-9));
}

#[test]
fn fine_point_adds_settle_time() {
    let acc = AccelLimits { settle: 0.05, ..accel(10_000.0) };
    let planned = plan_all(&FAST, acc, &[linear(at(1000.0, 0.0, 0.0), 1000.0, ZoneData::FINE)]);
    assert!(close(planned[0].duration(), 1.15, 1e-9));
    assert!(close(planned[0].zone_entry, 1.1, 1e-9));
}

#[test]
fn movej_limiting_axis_sets_the_pace() {
    // Axis 1 moves 100 at 100/s, axis 2 moves 20: axis 1 limits. Axes reach
    // full speed at 1000/s²: T = 100/100 + 100/1000, and both finish together.
    let robot = Gantry { speeds: [100.0; 6] };
    let acc = AccelLimits { tcp: 1e6, ori: 1e6, joint: [1000.0; 6], settle: 0.0 };
    let to = [100.0, 20.0, 0.0, 0.0, 0.0, 0.0];
    let request = MoveRequest {
        target: Target::Joints(to),
        speed: speed(5000.0, 500.0),
        ..linear(at(0.0, 0.0, 0.0), 0.0, ZoneData::FINE)
    };
    let planned = plan_all(&robot, acc, &[request]);
    assert!(close(planned[0].duration(), 1.1, 1e-9));
    // At the end of the ramp (0.1 s) axis 1 has covered a·t²/2 = 5, axis 2 a fifth.
    let ramp = planned[0].sample(&robot, 0.1);
    assert!(close(ramp.joints[0], 5.0, 1e-9) && close(ramp.joints[1], 1.0, 1e-9));
    let half = planned[0].sample(&robot, 0.55);
    assert!(close(half.joints[0], 50.0, 1e-9) && close(half.joints[1], 10.0, 1e-9));
    // TCP speed at cruise: √(100² + 20²) mm/s.
    assert!(close(half.tcp_speed, (100.0f64 * 100.0 + 20.0 * 20.0).sqrt(), 1e-3));
    assert_eq!(planned[0].sample(&robot, 2.0).joints, to);
}

#[test]
fn movej_tcp_speed_bounds_the_pace() {
    // 100 mm at v_tcp 50 with axes at 1000 mm/s²: T = 100/50 + 50/1000.
    let robot = Gantry { speeds: [100.0; 6] };
    let acc = AccelLimits { tcp: 1e6, ori: 1e6, joint: [1000.0; 6], settle: 0.0 };
    let request = MoveRequest {
        target: Target::Joints([100.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
        speed: speed(50.0, 500.0),
        ..linear(at(0.0, 0.0, 0.0), 0.0, ZoneData::FINE)
    };
    let planned = plan_all(&robot, acc, &[request]);
    assert!(close(planned[0].duration(), 2.05, 1e-9));
}

/// A 100 mm square at v500, corners in `zone`, ending fine where it started.
fn square(zone: ZoneData) -> Vec<MoveRequest> {
    let corners = [(100.0, 0.0), (100.0, 100.0), (0.0, 100.0), (0.0, 0.0)];
    let last = corners.len() - 1;
    corners
        .iter()
        .enumerate()
        .map(|(i, &(x, y))| linear(at(x, y, 0.0), 500.0, if i == last { ZoneData::FINE } else { zone }))
        .collect()
}

#[test]
fn square_with_fine_points() {
    // Each side: 100/500 + 500/20000.
    let planned = plan_all(&FAST, accel(20_000.0), &square(ZoneData::FINE));
    let total = planned.last().unwrap().end;
    assert!(close(total, 4.0 * 0.225, 1e-9));
}

#[test]
fn square_with_z10_corners() {
    let z10 = ZoneData::predefined("z10").unwrap();
    let planned = plan_all(&FAST, accel(20_000.0), &square(z10));
    // Sides run 0→90, 10→90, 10→90, 10→100 mm; the 90° parabolas (d = 10) are
    // blends of 2d/v = 0.04 s each. First and last sides: 6.25 mm of ramp in
    // 0.025 s and 83.75 mm at 500; middle sides 80 mm at 500.
    let expected = 2.0 * (0.025 + 83.75 / 500.0) + 2.0 * (80.0 / 500.0) + 3.0 * 0.04;
    let total = planned.last().unwrap().end;
    assert!(close(total, expected, 1e-9), "{total} vs {expected}");
    assert!(total < 0.9);
    assert!(planned[..3].iter().all(|m| close(m.corner_time, 0.04, 1e-9) && m.zone == 10.0));
    assert!(!planned.iter().any(|m| m.corner_path_failure));

    // Closest approach to the corner: d·sin(θ/2)/2; speed there v·cos(θ/2).
    let corner = &planned[0];
    let (mut best, mut speed_there) = (f64::INFINITY, 0.0);
    let mut t = corner.zone_entry;
    while t <= corner.end {
        let s = corner.sample(&FAST, t);
        let d = (s.tcp.translation.vector - Vector3::new(100.0, 0.0, 0.0)).norm();
        if d < best {
            (best, speed_there) = (d, s.tcp_speed);
        }
        t += 1e-6;
    }
    assert!(close(best, 10.0 * FRAC_1_SQRT_2 / 2.0, 1e-4), "{best}");
    assert!(close(speed_there, 500.0 * FRAC_1_SQRT_2, 0.1), "{speed_there}");
}

#[test]
fn zone_is_reduced_to_half_the_neighbour_distance() {
    // z50 between 30 mm sides: the zone shrinks to 15 mm.
    let z50 = ZoneData::predefined("z50").unwrap();
    let moves = [linear(at(30.0, 0.0, 0.0), 100.0, z50), linear(at(30.0, 30.0, 0.0), 100.0, ZoneData::FINE)];
    let planned = plan_all(&FAST, accel(20_000.0), &moves);
    assert_eq!(planned[0].zone, 15.0);
    // The corner takes the whole of both sides: blend 2·15/100 s.
    assert!(close(planned[0].corner_time, 0.3, 1e-9));
    let mut best = f64::INFINITY;
    for k in 0..=3000 {
        let t = planned[0].zone_entry + planned[0].corner_time * k as f64 / 3000.0;
        let p = planned[0].sample(&FAST, t).tcp.translation.vector;
        best = best.min((p - Vector3::new(30.0, 0.0, 0.0)).norm());
    }
    assert!(close(best, 15.0 * FRAC_1_SQRT_2 / 2.0, 1e-3), "{best}");
}

#[test]
fn fly_by_without_a_successor_is_a_corner_path_failure() {
    let z10 = ZoneData::predefined("z10").unwrap();
    let mut planner = Planner::new([0.0; 6], accel(10_000.0));
    assert_eq!(planner.push(&FAST, &linear(at(1000.0, 0.0, 0.0), 1000.0, z10)), Ok(None));
    assert!(planner.has_pending());
    assert!(close(planner.pending_stop_time().unwrap(), 1.1, 1e-9));
    let planned = planner.flush().unwrap();
    assert!(planned.corner_path_failure);
    assert!(close(planned.duration(), 1.1, 1e-9));
    assert_eq!(planner.pending_stop_time(), None);
}

#[test]
fn orientation_speed_limits_movel() {
    // 100 mm while turning 90° at v_ori 100 °/s: the TCP slows to 100·100/90
    // mm/s; T = L/v + v/a.
    let request =
        MoveRequest { speed: speed(1000.0, 100.0), ..linear(turned(100.0, 0.0, 0.0, 90.0), 0.0, ZoneData::FINE) };
    let planned = plan_all(&FAST, accel(10_000.0), &[request]);
    let v = 100.0 * 100.0 / 90.0;
    assert!(close(planned[0].duration(), 100.0 / v + v / 10_000.0, 1e-9));
    let end = planned[0].sample(&FAST, planned[0].end);
    assert!(close(end.joints[3], 90.0, 1e-6));
}

#[test]
fn pure_reorientation_with_zero_tcp_speed() {
    // v_tcp = 0 and the TCP stays: 90° at 100 °/s with 1000 °/s².
    let acc = AccelLimits { ori: 1000.0, ..accel(10_000.0) };
    let request = MoveRequest { speed: speed(0.0, 100.0), ..linear(turned(0.0, 0.0, 0.0, 90.0), 0.0, ZoneData::FINE) };
    let planned = plan_all(&FAST, acc, &[request]);
    assert!(close(planned[0].duration(), 0.9 + 0.1, 1e-9));
    let mid = planned[0].sample(&FAST, 0.5);
    assert_eq!(mid.tcp_speed, 0.0);
    assert!(close(mid.joints[3], 45.0, 1e-6));
}

#[test]
fn axis_speed_slows_movel() {
    // Axis 1 (x) may only do 200 mm/s: the programmed 1000 mm/s drops to 200.
    let robot = Gantry { speeds: [200.0, 1e5, 1e5, 1e5, 1e5, 1e5] };
    let planned = plan_all(&robot, accel(10_000.0), &[linear(at(1000.0, 0.0, 0.0), 1000.0, ZoneData::FINE)]);
    assert!(close(planned[0].duration(), 1000.0 / 200.0 + 200.0 / 10_000.0, 1e-9));
}

#[test]
fn movec_quarter_circle() {
    let r = 100.0;
    let h = r * FRAC_1_SQRT_2;
    let moves = [
        linear(at(r, 0.0, 0.0), 500.0, ZoneData::FINE),
        MoveRequest {
            target: Target::Circular { via: at(h, h, 0.0), to: at(0.0, r, 0.0) },
            ..linear(at(0.0, 0.0, 0.0), 500.0, ZoneData::FINE)
        },
    ];
    let planned = plan_all(&FAST, accel(10_000.0), &moves);
    // Length πr/2 at 500 mm/s: T = L/v + v/a.
    assert!(close(planned[1].duration(), PI * r / 2.0 / 500.0 + 0.05, 1e-9));
    let mid = planned[1].sample(&FAST, (planned[1].start + planned[1].end) / 2.0);
    assert!(close(mid.tcp.translation.vector.norm(), r, 1e-9));
}

#[test]
fn degenerate_circle_is_an_error() {
    let mut planner = Planner::new([0.0; 6], accel(10_000.0));
    let request = MoveRequest {
        target: Target::Circular { via: at(50.0, 0.0, 0.0), to: at(100.0, 0.0, 0.0) },
        ..linear(at(0.0, 0.0, 0.0), 500.0, ZoneData::FINE)
    };
    assert_eq!(planner.push(&FAST, &request), Err(MotionError::DegenerateCircle));
    assert!(!planner.has_pending());
}

#[test]
fn degenerate_inputs_give_errors_or_zero_time() {
    let mut planner = Planner::new([0.0; 6], accel(10_000.0));
    // The same point again: zero length, zero time, no NaN.
    let same = linear(at(0.0, 0.0, 0.0), 1000.0, ZoneData::FINE);
    assert_eq!(planner.push(&FAST, &same), Ok(None));
    let planned = planner.flush().unwrap();
    assert_eq!(planned.duration(), 0.0);
    let s = planned.sample(&FAST, f64::NAN);
    assert!(s.joints.iter().all(|q| q.is_finite()) && s.tcp_speed == 0.0);
    // A TCP move with no TCP speed, a NaN target, a target past a joint limit.
    assert!(matches!(
        planner.push(&FAST, &linear(at(10.0, 0.0, 0.0), 0.0, ZoneData::FINE)),
        Err(MotionError::InvalidData(_))
    ));
    assert!(matches!(
        planner.push(&FAST, &linear(at(f64::NAN, 0.0, 0.0), 100.0, ZoneData::FINE)),
        Err(MotionError::InvalidData(_))
    ));
    let zero_quat = rapid_motion::pose::pose([0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]);
    assert!(matches!(planner.push(&FAST, &linear(zero_quat, 100.0, ZoneData::FINE)), Err(MotionError::InvalidData(_))));
    let far = linear(at(2e6, 0.0, 0.0), 100.0, ZoneData::FINE);
    assert_eq!(planner.push(&FAST, &far), Err(MotionError::OutOfReach));
    let past = MoveRequest { target: Target::Joints([0.0, 0.0, 0.0, 0.0, 95.0, 0.0]), ..same };
    assert_eq!(planner.push(&FAST, &past), Err(MotionError::JointLimit { axis: 5 }));
    assert!(planner.flush().is_none());
}

#[test]
fn samples_share_one_grid() {
    let z10 = ZoneData::predefined("z10").unwrap();
    let planned = plan_all(&FAST, accel(20_000.0), &square(z10));
    let times: Vec<f64> = planned.iter().flat_map(|m| m.samples(&FAST, DEFAULT_STEP).map(|s| s.time)).collect();
    let end = planned.last().unwrap().end;
    assert_eq!(times.len(), (end / DEFAULT_STEP).ceil() as usize);
    assert!(times.windows(2).all(|w| close(w[1] - w[0], DEFAULT_STEP, 1e-9)));
    assert_eq!(planned[0].samples(&FAST, 0.0).count(), 0);
    assert_eq!(planned[0].samples(&FAST, f64::NAN).count(), 0);
}

#[test]
fn accset_and_velset_scale_the_move() {
    // AccSet 50: a = 5000; VelSet 50 %: v = 500. T = 1000/500 + 500/5000.
    let mut planner = Planner::new([0.0; 6], accel(10_000.0));
    planner.set_settings(MotionSettings { acc: 50.0, vel_override: 50.0, ..MotionSettings::default() });
    assert_eq!(planner.push(&FAST, &linear(at(1000.0, 0.0, 0.0), 1000.0, ZoneData::FINE)), Ok(None));
    assert!(close(planner.flush().unwrap().duration(), 2.1, 1e-9));
}

#[test]
fn joint_moves_blend_per_joint() {
    // Two joint moves at right angles with z10: the corner is a joint-space
    // parabola that passes inside the via point and saves time over fine.
    let robot = Gantry { speeds: [100.0; 6] };
    let acc = AccelLimits { tcp: 1e6, ori: 1e6, joint: [1000.0; 6], settle: 0.0 };
    let joint = |q: Joints, zone| MoveRequest {
        target: Target::Joints(q),
        speed: speed(5000.0, 500.0),
        zone,
        tool: Pose::identity(),
        held_object: None,
        wobj: Pose::identity(),
    };
    let z10 = ZoneData::predefined("z10").unwrap();
    let via = [100.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let end = [100.0, 100.0, 0.0, 0.0, 0.0, 0.0];
    let fly = plan_all(&robot, acc, &[joint(via, z10), joint(end, ZoneData::FINE)]);
    let stop = plan_all(&robot, acc, &[joint(via, ZoneData::FINE), joint(end, ZoneData::FINE)]);
    assert!(close(stop[1].end, 2.2, 1e-9));
    // 0.95 s into the corner, 0.2 s of corner, 0.95 s out of it.
    assert!(close(fly[1].end, 2.1, 1e-9));
    // 10 mm of a 100 mm TCP distance: the zone is 10 % of each joint move; a
    // 90° corner at 100/s then is the same parabola as in TCP space.
    assert!(close(fly[0].corner_time, 0.2, 1e-9));
    let mut best = f64::INFINITY;
    for k in 0..=2000 {
        let t = fly[0].zone_entry + fly[0].corner_time * k as f64 / 2000.0;
        let q = fly[0].sample(&robot, t).joints;
        best = best.min(((q[0] - 100.0).powi(2) + q[1].powi(2)).sqrt());
    }
    assert!(close(best, 10.0 * FRAC_1_SQRT_2 / 2.0, 1e-3), "{best}");
}

#[test]
fn short_fly_by_zigzag_stays_continuous() {
    // Points 4 to 40 mm apart with z50 zones that all shrink to half the
    // distance, at v1000: whatever the planner chooses, the trajectory must be
    // finite, on one time axis, and never jump. (A property, not hand numbers.)
    let z50 = ZoneData::predefined("z50").unwrap();
    let mut moves = Vec::new();
    let (mut x, mut y) = (0.0, 0.0);
    for i in 0..40 {
        let step = 4.0 + (i % 10) as f64 * 4.0;
        if i % 2 == 0 {
            x += step
        } else {
            y += if i % 4 == 1 { step } else { -step }
        }
        let zone = if i == 39 { ZoneData::FINE } else { z50 };
        moves.push(linear(turned(x, y, 0.0, (i % 7) as f64), 1000.0, zone));
    }
    let planned = plan_all(&FAST, accel(10_000.0), &moves);
    assert_eq!(planned.len(), 40);
    assert!(planned.iter().filter(|m| m.corner_time > 0.0).count() >= 30);
    assert!(planned.windows(2).all(|w| w[0].end == w[1].start));
    let samples: Vec<_> = planned.iter().flat_map(|m| m.samples(&FAST, 0.001)).collect();
    for pair in samples.windows(2) {
        let jump = (pair[1].tcp.translation.vector - pair[0].tcp.translation.vector).norm();
        assert!(jump <= 1000.0 * 0.001 * 1.01 + 1e-9, "{jump} mm in 1 ms at {}", pair[0].time);
        assert!(pair[0].joints.iter().all(|q| q.is_finite()) && pair[0].tcp_speed <= 1000.0 * 1.01);
        // Speed changes no faster than the path acceleration (10 mm/s per ms).
        let dv = (pair[1].tcp_speed - pair[0].tcp_speed).abs();
        assert!(dv <= 10.0 * 1.01, "{dv} mm/s in 1 ms at {}", pair[0].time);
    }
}

/// A polar robot: axis 1 turns about z (°), axis 2 is the radius and axis 3
/// the height (mm); axis 4 turns the wrist so the tool keeps its heading.
struct Polar;

impl Kinematics for Polar {
    fn forward(&self, q: &Joints) -> Pose {
        let a = q[0].to_radians();
        let heading = UnitQuaternion::from_euler_angles(0.0, 0.0, (q[0] + q[3]).to_radians());
        Isometry3::from_parts(Translation3::new(q[1] * a.cos(), q[1] * a.sin(), q[2]), heading)
    }

    fn inverse(&self, flange: &Pose) -> Vec<Joints> {
        let t = flange.translation.vector;
        let turn = t.y.atan2(t.x).to_degrees();
        let wrist = (flange.rotation.euler_angles().2.to_degrees() - turn + 540.0).rem_euclid(360.0) - 180.0;
        vec![[turn, t.x.hypot(t.y), t.z, wrist, 0.0, 0.0]]
    }

    fn limits(&self) -> [(f64, f64); 6] {
        [(-180.0, 180.0), (0.0, 1e4), (-1e4, 1e4), (-180.0, 180.0), (-1.0, 1.0), (-1.0, 1.0)]
    }

    fn max_speeds(&self) -> [f64; 6] {
        [90.0, 1e5, 1e5, 1e5, 1e5, 1e5]
    }
}

#[test]
fn movel_slows_where_an_axis_would_be_too_fast() {
    // A line past axis 1 at 100 mm: axis 1 turns at v/100 rad/s at the closest
    // point, so with 90 °/s the TCP may do at most 100·π/2 = 157.08 mm/s there.
    // The planner samples the path every 20 mm, which sees a little less than
    // the peak: 20 mm per atan(0.2) = 11.31° of axis 1, i.e. 159.15 mm/s.
    let mut planner = Planner::new([-45.0, 100.0 * 2f64.sqrt(), 0.0, 45.0, 0.0, 0.0], accel(10_000.0));
    assert_eq!(planner.push(&Polar, &linear(at(100.0, 100.0, 0.0), 1000.0, ZoneData::FINE)), Ok(None));
    let planned = planner.flush().unwrap();
    let time_at = |v: f64| 200.0 / v + v / 10_000.0;
    let t = planned.duration();
    assert!(t <= time_at(157.08) && t >= time_at(159.16), "{t}");
    let mid = planned.sample(&Polar, planned.start + t / 2.0);
    assert!(close(mid.joints[0], 0.0, 1e-6) && close(mid.tcp.translation.y, 0.0, 1e-6));
}

#[test]
fn corner_across_a_change_of_interpolation() {
    // MoveL 100 mm at v100 with z10, then MoveJ 100 along y (axes at 100/s and
    // 1000/s², TCP acceleration 1000 mm/s²): the corner is a joint-space
    // parabola, so the sums match the all-joint case. MoveL: 5 mm of ramp in
    // 0.1 s, 85 mm at 100 in 0.85 s; corner 2·10/100 = 0.2 s; MoveJ from 10 %
    // on: 85 % at full speed in 0.85 s, ramp down in 0.1 s. Total 2.1 s.
    let robot = Gantry { speeds: [100.0; 6] };
    let acc = AccelLimits { tcp: 1000.0, ori: 1e6, joint: [1000.0; 6], settle: 0.0 };
    let z10 = ZoneData::predefined("z10").unwrap();
    let to_joints = MoveRequest {
        target: Target::Joints([100.0, 100.0, 0.0, 0.0, 0.0, 0.0]),
        ..linear(at(0.0, 0.0, 0.0), 5000.0, ZoneData::FINE)
    };
    let planned = plan_all(&robot, acc, &[linear(at(100.0, 0.0, 0.0), 100.0, z10), to_joints]);
    assert!(close(planned[0].corner_time, 0.2, 1e-6), "{}", planned[0].corner_time);
    assert!(close(planned[1].end, 2.1, 1e-6), "{}", planned[1].end);
    // And back: MoveJ with z10 into a MoveL.
    let from_joints = MoveRequest { zone: z10, target: Target::Joints([100.0, 0.0, 0.0, 0.0, 0.0, 0.0]), ..to_joints };
    let planned = plan_all(&robot, acc, &[from_joints, linear(at(100.0, 100.0, 0.0), 100.0, ZoneData::FINE)]);
    assert!(close(planned[1].end, 2.1, 1e-6), "{}", planned[1].end);
}

#[test]
fn speed_changes_inside_the_corner() {
    // v500 into a 90° z10 corner, v100 out of it: the corner starts at 500 and
    // ends at 100, its parameter rate changing linearly, so it takes
    // 4d/(v_in + v_out) = 40/600 s.
    let z10 = ZoneData::predefined("z10").unwrap();
    let moves = [linear(at(100.0, 0.0, 0.0), 500.0, z10), linear(at(100.0, 100.0, 0.0), 100.0, ZoneData::FINE)];
    let planned = plan_all(&FAST, accel(20_000.0), &moves);
    assert!(close(planned[0].corner_time, 40.0 / 600.0, 1e-9));
    let entry = planned[0].sample(&FAST, planned[0].zone_entry + 1e-9);
    let exit = planned[0].sample(&FAST, planned[0].end - 1e-9);
    assert!(close(entry.tcp_speed, 500.0, 1e-3) && close(exit.tcp_speed, 100.0, 1e-3));
    // The second side then runs 10 → 100 mm at 100 and brakes: 90/100 + 100/40000.
    assert!(close(planned[1].duration(), 0.9 + 0.0025, 1e-9));
}

#[test]
fn circles_blend_into_lines() {
    // MoveL, MoveC (half circle of r = 50) and MoveL, all with z10: corners
    // between lines and arcs, and the trajectory stays continuous.
    let z10 = ZoneData::predefined("z10").unwrap();
    let arc = MoveRequest {
        target: Target::Circular { via: at(250.0, 50.0, 0.0), to: at(200.0, 100.0, 0.0) },
        ..linear(at(0.0, 0.0, 0.0), 500.0, z10)
    };
    let moves = [linear(at(200.0, 0.0, 0.0), 500.0, z10), arc, linear(at(0.0, 100.0, 0.0), 500.0, ZoneData::FINE)];
    let planned = plan_all(&FAST, accel(20_000.0), &moves);
    assert!(planned[..2].iter().all(|m| m.zone == 10.0 && m.corner_time > 0.0));
    let samples: Vec<_> = planned.iter().flat_map(|m| m.samples(&FAST, 0.0005)).collect();
    for pair in samples.windows(2) {
        let jump = (pair[1].tcp.translation.vector - pair[0].tcp.translation.vector).norm();
        assert!(jump <= 500.0 * 0.0005 * 1.01 + 1e-9, "{jump} at {}", pair[0].time);
    }
    // Half way along the arc the TCP is on the circle, 50 mm from its centre.
    let mid = planned[1].sample(&FAST, (planned[1].start + planned[1].zone_entry) / 2.0);
    assert!(close((mid.tcp.translation.vector - Vector3::new(200.0, 50.0, 0.0)).norm(), 50.0, 1e-6));
}

#[test]
fn reorientation_zone_starts_turning_before_the_corner() {
    // Side 1 keeps the tool still; side 2 turns it 90° over 100 mm (0.9°/mm).
    // z10 has pzone_ori 15 mm: the turn fades in from 15 mm before the point,
    // as (x² · 15 mm) of side 2's rotation at progress x through the 30 mm zone.
    let z10 = ZoneData::predefined("z10").unwrap();
    let moves = [
        linear(at(100.0, 0.0, 0.0), 500.0, z10),
        MoveRequest { speed: speed(500.0, 500.0), ..linear(turned(100.0, 100.0, 0.0, 90.0), 0.0, ZoneData::FINE) },
    ];
    let planned = plan_all(&FAST, accel(20_000.0), &moves);
    let turn = |t: f64, m: &PlannedMove| m.sample(&FAST, t).tcp.rotation.angle().to_degrees();
    // 88 mm along side 1 (after the 6.25 mm ramp, at 500 mm/s): x = 0.1.
    let t88 = 0.025 + (88.0 - 6.25) / 500.0;
    assert!(close(planned[0].sample(&FAST, t88).tcp.translation.x, 88.0, 1e-9));
    assert!(close(turn(t88, &planned[0]), 0.01 * 15.0 * 0.9, 1e-9));
    // Before the zone nothing turns.
    assert!(turn(0.025 + (84.0 - 6.25) / 500.0, &planned[0]) < 1e-9);
    // Corner exit, 10 mm into side 2: x = 25/30.
    assert!(close(turn(planned[0].end, &planned[0]), (25.0f64 / 30.0).powi(2) * 15.0 * 0.9, 1e-9));
    // Zone exit (15 mm into side 2, 5 mm after the corner at 500 mm/s): 13.5°,
    // and from there on the plain interpolation: 45° at 50 mm.
    assert!(close(turn(planned[1].start + 0.01, &planned[1]), 13.5, 1e-9));
    assert!(close(turn(planned[1].start + 0.08, &planned[1]), 45.0, 1e-9));
}

/// Reorientation without TCP movement: v_ori 100 °/s, reached in 0.1 s (1000 °/s²).
fn turning(to: Pose, zone: ZoneData) -> MoveRequest {
    MoveRequest { speed: speed(1000.0, 100.0), ..linear(to, 0.0, zone) }
}

/// A zone of 10° for reorientations (zone_ori); its position zone is no use to a
/// standing TCP.
fn ori_zone(deg: f64) -> ZoneData {
    ZoneData {
        finep: false,
        pzone_tcp: 10.0,
        pzone_ori: 15.0,
        pzone_eax: 15.0,
        zone_ori: deg,
        zone_leax: 15.0,
        zone_reax: deg,
    }
}

const ORI_ACC: AccelLimits = AccelLimits { tcp: 1e6, ori: 1000.0, joint: [1e6; 6], settle: 0.0 };

#[test]
fn reorientations_of_a_standing_tcp_blend_in_the_orientation_zone() {
    // §2.2.3: without TCP movement the zone is an angle. 0° → 30° → 60° about z with
    // zone_ori 10° at 30°: a straight corner from 20° to 40° at 100 °/s, so both take
    // what one turn of 60° takes: 60/100 + 0.1 = 0.7 s (0.8 s stopping at 30°).
    let moves =
        [turning(turned(0.0, 0.0, 0.0, 30.0), ori_zone(10.0)), turning(turned(0.0, 0.0, 0.0, 60.0), ZoneData::FINE)];
    let planned = plan_all(&FAST, ORI_ACC, &moves);
    assert_eq!(planned.len(), 2);
    // Before the corner: 0.1 s up to speed (5°), 15° at 100 °/s: 0.25 s.
    assert!(close(planned[0].zone_entry, 0.25, 1e-9), "entry {}", planned[0].zone_entry);
    assert!(close(planned[0].corner_time, 0.2, 1e-9), "corner {}", planned[0].corner_time);
    assert!(close(planned[1].end, 0.7, 1e-9), "end {}", planned[1].end);
    // Half way through the corner the tool has turned 30°, the TCP still at the origin.
    let mid = planned[0].sample(&FAST, 0.35);
    assert!(close(mid.joints[3], 30.0, 1e-6) && mid.tcp.translation.vector.norm() < 1e-9, "{:?}", mid.joints);
    assert_eq!(mid.tcp_speed, 0.0);
}

#[test]
fn a_reorientation_corner_turning_to_another_axis() {
    // 30° about z, then 30° about the tool's x, zone_ori 10°: the corner's legs are
    // 10° each at 90° in rotation vectors. Its speed could reach √(1000 · 10 / sin 45°)
    // = 119 °/s, so it is walked at 100 °/s: parameter rates 100 / 20 at both ends, 0.2 s.
    // The moves around it as above: 0.25 s each; 0.7 s in all.
    let second = turned(0.0, 0.0, 0.0, 30.0) * UnitQuaternion::from_euler_angles(30f64.to_radians(), 0.0, 0.0);
    let moves = [turning(turned(0.0, 0.0, 0.0, 30.0), ori_zone(10.0)), turning(second, ZoneData::FINE)];
    let planned = plan_all(&FAST, ORI_ACC, &moves);
    assert!(close(planned[0].corner_time, 0.2, 1e-9), "corner {}", planned[0].corner_time);
    assert!(close(planned[1].end, 0.7, 1e-9), "end {}", planned[1].end);
    // Half way along the parabola: rotation vector (a + 2p + b)/4 = (2.5°, 0, −2.5°) in
    // the tool frame at the point; the TCP stands.
    let mid = planned[0].sample(&FAST, 0.35);
    let at_point = turned(0.0, 0.0, 0.0, 30.0).rotation;
    let expected = at_point * UnitQuaternion::from_scaled_axis(Vector3::new(2.5, 0.0, -2.5).map(f64::to_radians));
    assert!(mid.tcp.rotation.angle_to(&expected) < 1e-9, "{:?}", mid.joints);
    assert!(mid.tcp.translation.vector.norm() < 1e-9);
}

#[test]
fn a_reorientation_next_to_a_tcp_move_stops() {
    // §2.2.3: no corner between a move of the TCP and a reorientation without one.
    let moves =
        [linear(at(100.0, 0.0, 0.0), 100.0, ori_zone(10.0)), turning(turned(100.0, 0.0, 0.0, 30.0), ZoneData::FINE)];
    let planned = plan_all(&FAST, ORI_ACC, &moves);
    assert_eq!(planned[0].corner_time, 0.0);
}

#[test]
fn a_zone_that_is_no_positive_number_is_a_stop_point() {
    // NaN and negative zones leave no room for a corner (f64::min would pass a NaN by
    // and take half the neighbour distance instead).
    for bad in [f64::NAN, -5.0] {
        let moves =
            [turning(turned(0.0, 0.0, 0.0, 30.0), ori_zone(bad)), turning(turned(0.0, 0.0, 0.0, 60.0), ZoneData::FINE)];
        assert_eq!(plan_all(&FAST, ORI_ACC, &moves)[0].corner_time, 0.0, "zone_ori {bad}");
        let zone = ZoneData { pzone_tcp: bad, ..ori_zone(10.0) };
        let moves = [linear(at(100.0, 0.0, 0.0), 100.0, zone), linear(at(100.0, 100.0, 0.0), 100.0, ZoneData::FINE)];
        assert_eq!(plan_all(&FAST, accel(10_000.0), &moves)[0].corner_time, 0.0, "pzone_tcp {bad}");
    }
}

#[test]
fn a_new_work_object_makes_the_corner_joint_interpolated() {
    // §2.2.3: where the coordinate system changes in a corner, a new TCP or a new
    // work object, the corner path is joint-interpolated. The square's sides in one
    // work object blend on TCP parabolas; each side in a work object of its own (its
    // frame elsewhere, the targets the same in the base frame) blends in joint space.
    let z10 = ZoneData::predefined("z10").unwrap();
    let kinds = |moves: &[MoveRequest]| -> Vec<Option<CornerKind>> {
        plan_all(&FAST, accel(20_000.0), moves).iter().map(PlannedMove::corner_kind).collect()
    };
    let tcp = Some(CornerKind::Tcp);
    assert_eq!(kinds(&square(z10)), [tcp, tcp, tcp, None]);
    let one_wobj = at(500.0, 0.0, 0.0);
    let same: Vec<MoveRequest> = square(z10).into_iter().map(|m| MoveRequest { wobj: one_wobj, ..m }).collect();
    assert_eq!(kinds(&same), [tcp, tcp, tcp, None]);
    let own: Vec<MoveRequest> = square(z10)
        .into_iter()
        .enumerate()
        .map(|(i, m)| MoveRequest { wobj: turned(0.0, 0.0, 0.0, 10.0 * i as f64), ..m })
        .collect();
    let joint = Some(CornerKind::Joint);
    assert_eq!(kinds(&own), [joint, joint, joint, None]);
}

/// A straight move 60 mm down from `start` on the IRB 120, its orientation kept.
fn down_from(start: Joints) -> (rapid_motion::Opw, MoveRequest) {
    let kin = rapid_motion::default_model().kinematics();
    let from = kin.forward(&start);
    let to = Isometry3::from_parts(
        Translation3::from(from.translation.vector - Vector3::new(0.0, 0.0, 60.0)),
        from.rotation,
    );
    (kin, linear(to, 100.0, ZoneData::FINE))
}

#[test]
fn a_linear_move_whose_axis_would_leave_its_range_stops_there() {
    // From [0,0,0,45,3,0] (axis 5 near the wrist singularity) straight down 60 mm with
    // the orientation kept, axis 4 turns from 45° past its 160° limit, to 166.76° (an
    // independent inverse kinematics, tests/hand/). The solver's nearest solution
    // within the ranges there has axes 4 and 6 half a turn away: the arm cannot jump,
    // the move is refused with the axis.
    let (kin, down) = down_from([0.0, 0.0, 0.0, 45.0, 3.0, 0.0]);
    let mut planner = Planner::new([0.0, 0.0, 0.0, 45.0, 3.0, 0.0], accel(10_000.0));
    assert_eq!(planner.push(&kin, &down).err(), Some(MotionError::JointLimit { axis: 4 }));
}

#[test]
fn near_the_wrist_singularity_axes_4_and_6_turn_fast_but_continuously() {
    // From [0,0,0,60,10,0] the same move turns axis 4 from 60° to 125.12° and axis 6
    // to -65.97° (tests/hand/), within their ranges: the move is made, its joints
    // change by small steps all the way, and it ends where the calculation says.
    let start = [0.0, 0.0, 0.0, 60.0, 10.0, 0.0];
    let (kin, down) = down_from(start);
    let mut planner = Planner::new(start, accel(10_000.0));
    let mut planned: Vec<PlannedMove> = planner.push(&kin, &down).unwrap().into_iter().collect();
    planned.extend(planner.flush());
    let end = planned[0].end_joints;
    let expected = [0.0, -1.66, 12.84, 125.12, 10.59, -65.97];
    assert!(end.iter().zip(expected).all(|(a, b)| (a - b).abs() < 0.01), "{end:?}");
    let mut t = planned[0].start;
    let mut last = planned[0].sample(&kin, t).joints;
    while t < planned[0].end {
        t += 0.004;
        let q = planned[0].sample(&kin, t.min(planned[0].end)).joints;
        assert!(q.iter().zip(last).all(|(a, b)| (a - b).abs() < 10.0), "a jump at {t} s: {last:?} → {q:?}");
        last = q;
    }
}
