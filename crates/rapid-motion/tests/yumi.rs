//! The IRB 14000 YuMi's arms: forward kinematics against tables worked by hand from
//! the URDF's joint origins (kinematics/yumi.rs cites them), the arm angle, and the
//! numeric inverse kinematics' round trips and refusals.
//!
//! In the arm's own frame (axis 1's, before it turns) the chain at all axes 0 runs,
//! in mm: axis 2 at (30, 0, 100) turned +90° about x; axis 7 at (30 − 30, 0,
//! 100 + 172.83) = (0, 0, 272.83), back to the arm frame's orientation (so axis 7 is
//! coaxial with axis 1); axis 3 at (−41.88, 0, 351.56), its frame Ry(−90°)·Rx(90°)
//! (x = (0, 0, 1), y = (−1, 0, 0), z = (0, −1, 0)); axis 4 at (−41.88 − 164.61, 0,
//! 351.56 + 40.5) = (−206.49, 0, 392.06) (x = (0, 0, 1), y = (0, 1, 0), z = (−1, 0,
//! 0)); axis 5 at (−206.49 − 100.39, 0, 392.06 − 27) = (−306.88, 0, 365.06); axis 6
//! and tool0 at (−306.88 − 29, 0, 365.06 + 27) = (−335.88, 0, 392.06), tool0's
//! x = (0, 0, 1) and z = (−1, 0, 0).

use nalgebra::Vector3;
use rapid_motion::kinematics::yumi::{arm_angle, base, forward, inverse, limit_violation, Joints7, Side, LIMITS};
use rapid_motion::{MotionError, Pose};

const ZERO: Joints7 = [0.0; 7];

fn close(a: &Vector3<f64>, b: [f64; 3], tol: f64) -> bool {
    (a - Vector3::from(b)).norm() <= tol
}

/// tool0 in the arm's own frame (axis 1's frame before it turns).
fn in_arm(side: Side, joints: &Joints7) -> Pose {
    base(side).inverse() * forward(side, joints)
}

#[test]
fn axis_1_sits_on_the_body_where_the_urdf_puts_it() {
    // Axis 1's direction R·z for rpy (r, p, y): Rz(y)·Ry(p)·(0, −sin r, cos r) =
    // Rz(y)·(sin p cos r, −sin r, cos p cos r). Right arm (r, p, y) = (−0.9795, −0.5682,
    // −2.3155): (−0.3000, 0.8301, 0.4700) turned by −132.67° about z = (0.8137, −0.3420,
    // 0.4700). Left (0.9781, −0.5716, 2.3180): (−0.3023, −0.8293, 0.4700) turned by
    // 132.81° = (0.8138, 0.3418, 0.4700). A second public YuMi URDF gives the left axis
    // as (0.08138, 0.03421, 0.046985)/0.1, the same direction.
    for (side, at, axis) in [
        (Side::Right, [53.55, -72.5, 414.92], [0.8137, -0.3420, 0.4700]),
        (Side::Left, [53.55, 72.5, 414.92], [0.8138, 0.3418, 0.4700]),
    ] {
        let b = base(side);
        assert!(close(&b.translation.vector, at, 1e-9), "{side:?}");
        let z = b.rotation * Vector3::z();
        assert!(close(&z, axis, 1e-3), "{side:?}: {z:?}");
    }
}

#[test]
fn a_second_urdf_puts_the_left_axis_1_on_the_same_line() {
    // An independent public YuMi URDF (a `yumi_driver` package's) places the left axis 1
    // through (47.607, 70, 411.486) mm: a point 7.3 mm back along our axis 1.
    let b = base(Side::Left);
    let axis = b.rotation * Vector3::z();
    let d = Vector3::new(47.607, 70.0, 411.486) - b.translation.vector;
    let off_line = (d - axis * axis.dot(&d)).norm();
    assert!(off_line < 0.05, "{off_line}");
    assert!((axis.dot(&d) + 7.3).abs() < 0.05, "{}", axis.dot(&d));
}

/// Joints, then tool0's position, x axis and z axis in the arm's own frame.
type Row = (Joints7, [f64; 3], [f64; 3], [f64; 3]);

#[test]
fn forward_matches_the_hand_worked_table() {
    #[rustfmt::skip]
    let table: [Row; 6] = [
        // All axes 0: the table in the file's doc.
        (ZERO, [-335.88, 0.0, 392.06], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0]),
        // Axis 1 at 90° turns everything about the arm frame's z: (x, y) → (−y, x).
        ([90.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.0, -335.88, 392.06], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]),
        // Axis 7 is coaxial with axis 1 at zero (both on the arm frame's z): the same pose.
        ([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 90.0], [0.0, -335.88, 392.06], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]),
        // Axis 2 turns about its z, the arm frame's −y, through (30, 0, 100): +90° about
        // −y takes (x, z) to (−z, x); tool0 from the pivot (−365.88, 0, 292.06) →
        // (−292.06, 0, −365.88), so at (−262.06, 0, −265.88); x (0, 0, 1) → (−1, 0, 0),
        // z (−1, 0, 0) → (0, 0, −1).
        ([0.0, 90.0, 0.0, 0.0, 0.0, 0.0, 0.0], [-262.06, 0.0, -265.88], [-1.0, 0.0, 0.0], [0.0, 0.0, -1.0]),
        // Axis 6 turns tool0 about its own z (−x): the position stays, x (0, 0, 1) → (0, 1, 0).
        ([0.0, 0.0, 0.0, 0.0, 0.0, 90.0, 0.0], [-335.88, 0.0, 392.06], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]),
        // Axis 4 turns about its z (−x) through (−206.49, 0, 392.06): tool0 lies on that
        // line's height, offset (−129.39, 0, 0) along it: the position stays; x (0, 0, 1)
        // turned 90° about −x → (0, 1, 0).
        ([0.0, 0.0, 0.0, 90.0, 0.0, 0.0, 0.0], [-335.88, 0.0, 392.06], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]),
    ];
    for side in [Side::Left, Side::Right] {
        for (joints, at, x, z) in &table {
            let t = in_arm(side, joints);
            assert!(close(&t.translation.vector, *at, 1e-9), "{side:?} {joints:?}: {:?}", t.translation.vector);
            assert!(close(&(t.rotation * Vector3::x()), *x, 1e-9), "{side:?} {joints:?} x");
            assert!(close(&(t.rotation * Vector3::z()), *z, 1e-9), "{side:?} {joints:?} z");
        }
    }
}

#[test]
fn the_arms_mirror_each_other_across_the_body() {
    // The URDF's two bases are mirror images within 0.004 rad: the zero poses mirror in
    // the body's y to within a couple of millimetres.
    let l = forward(Side::Left, &ZERO).translation.vector;
    let r = forward(Side::Right, &ZERO).translation.vector;
    assert!((l.x - r.x).abs() < 2.0 && (l.y + r.y).abs() < 2.0 && (l.z - r.z).abs() < 2.0, "{l:?} {r:?}");
    // Reach: |(−335.88, 0, 392.06)| = 516.26 mm from axis 1's origin, 392.06 mm of it
    // along axis 1.
    let b = base(Side::Right);
    let d = forward(Side::Right, &ZERO).translation.vector - b.translation.vector;
    assert!((d.norm() - 516.26).abs() < 0.01, "{}", d.norm());
    assert!((d.dot(&(b.rotation * Vector3::z())) - 392.06).abs() < 1e-9);
}

#[test]
fn the_arm_angle_is_zero_at_calibration_and_follows_axis_7_not_axis_1() {
    for side in [Side::Left, Side::Right] {
        assert!(arm_angle(side, &ZERO).abs() < 1e-9, "{side:?}");
        // Axis 1 turns the elbow, the shoulder–wrist line and axis 1's plane together.
        assert!(arm_angle(side, &[40.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]).abs() < 1e-9);
        // With the lower arm leaning (axis 2), axis 7 swings the elbow out of axis 1's
        // plane: it changes the arm angle.
        let a = arm_angle(side, &[0.0, -40.0, -30.0, 0.0, 30.0, 0.0, 30.0]);
        let b = arm_angle(side, &[0.0, -40.0, -30.0, 0.0, 30.0, 0.0, -30.0]);
        assert!((a - b).abs() > 5.0, "{a} {b}");
    }
}

/// A deterministic xorshift in [0, 1).
fn rng(mut state: u64) -> impl FnMut() -> f64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn inverse_round_trips_random_reachable_joints() {
    let mut next = rng(0x2545_F491_4F6C_DD1D);
    let mut solved = 0;
    for k in 0..120 {
        let side = if k % 2 == 0 { Side::Left } else { Side::Right };
        // Joints well inside the limits, and a seed up to 10° off on every axis.
        let joints: Joints7 = std::array::from_fn(|i| {
            let (lo, hi) = LIMITS[i];
            let margin = 0.15 * (hi - lo);
            lo + margin + next() * (hi - lo - 2.0 * margin)
        });
        let seed: Joints7 = std::array::from_fn(|i| joints[i] + (next() - 0.5) * 20.0);
        let target = forward(side, &joints);
        let angle = arm_angle(side, &joints);
        let got = inverse(side, &target, angle, &seed).unwrap_or_else(|e| panic!("{e} for {joints:?}"));
        let back = forward(side, &got);
        assert!((back.translation.vector - target.translation.vector).norm() < 1e-5, "{got:?} for {joints:?}");
        assert!(back.rotation.angle_to(&target.rotation) < 1e-7);
        let da = (arm_angle(side, &got) - angle).rem_euclid(360.0);
        assert!(da.min(360.0 - da) < 1e-5, "arm angle {} for {angle}", arm_angle(side, &got));
        assert_eq!(limit_violation(&got), None);
        solved += 1;
    }
    assert_eq!(solved, 120);
}

#[test]
fn another_arm_angle_moves_the_elbow_not_the_tool() {
    let side = Side::Left;
    let joints = [10.0, -60.0, -20.0, 30.0, 40.0, 20.0, -15.0];
    let target = forward(side, &joints);
    let angle = arm_angle(side, &joints);
    let got = inverse(side, &target, angle + 20.0, &joints).expect("reachable with the elbow turned");
    assert!((forward(side, &got).translation.vector - target.translation.vector).norm() < 1e-5);
    let da = (arm_angle(side, &got) - angle - 20.0).rem_euclid(360.0);
    assert!(da.min(360.0 - da) < 1e-5);
    assert!(got.iter().zip(&joints).any(|(a, b)| (a - b).abs() > 1.0), "the joints must differ: {got:?}");
}

#[test]
fn targets_out_of_reach_are_refused() {
    let side = Side::Right;
    let far = Pose::translation(2000.0, 0.0, 400.0) * forward(side, &ZERO).rotation;
    assert_eq!(inverse(side, &far, 0.0, &ZERO), Err(MotionError::OutOfReach));
    let nan = Pose::translation(f64::NAN, 0.0, 0.0);
    assert_eq!(inverse(side, &nan, 0.0, &ZERO), Err(MotionError::OutOfReach));
    assert_eq!(inverse(side, &forward(side, &ZERO), f64::NAN, &ZERO), Err(MotionError::OutOfReach));
}

#[test]
fn limits_are_abb_numbered_axis_7_last() {
    assert_eq!(limit_violation(&ZERO), None);
    assert_eq!(limit_violation(&[0.0, 50.0, 0.0, 0.0, 0.0, 0.0, 0.0]), Some(2));
    assert_eq!(limit_violation(&[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 170.0]), Some(7));
    assert_eq!(limit_violation(&[0.0, 0.0, 90.0, 0.0, 0.0, 0.0, 0.0]), Some(3));
}

#[test]
fn inverse_with_axis_7_held_round_trips() {
    use rapid_motion::kinematics::yumi::inverse_locked;
    let mut next = rng(0x9E37_79B9_7F4A_7C15);
    for k in 0..60 {
        let side = if k % 2 == 0 { Side::Left } else { Side::Right };
        let joints: Joints7 = std::array::from_fn(|i| {
            let (lo, hi) = LIMITS[i];
            let margin = 0.15 * (hi - lo);
            lo + margin + next() * (hi - lo - 2.0 * margin)
        });
        let seed: [f64; 6] = std::array::from_fn(|i| joints[i] + (next() - 0.5) * 10.0);
        let target = forward(side, &joints);
        let got = inverse_locked(side, &target, joints[6], &seed).unwrap_or_else(|e| panic!("{e} for {joints:?}"));
        let back = forward(side, &[got[0], got[1], got[2], got[3], got[4], got[5], joints[6]]);
        assert!((back.translation.vector - target.translation.vector).norm() < 1e-5, "{got:?} for {joints:?}");
        assert!(back.rotation.angle_to(&target.rotation) < 1e-7);
    }
}

/// A YuMi arm in the planner: axis 7 rides in the external axes' eax_a.
mod planned {
    use super::*;
    use rapid_motion::external::ExternalMove;
    use rapid_motion::kinematics::yumi::calibration;
    use rapid_motion::plan::{AccelLimits, MoveRequest, Planner, SpeedData, Target, ZoneData, DEFAULT_STEP};
    use rapid_motion::{find_model, Kinematics};

    fn axis7_move(from: f64, to: f64) -> ExternalMove {
        let mut ext =
            ExternalMove { from: [from; 6], to: [from; 6], max_speed: [0.0; 6], acc: [0.0; 6], linear: [false; 6] };
        (ext.to[0], ext.max_speed[0], ext.acc[0]) = (to, 180.0, 1200.0);
        ext
    }

    fn request(target: Target) -> MoveRequest {
        let speed = SpeedData::predefined("v200").unwrap();
        let zone = ZoneData::predefined("fine").unwrap();
        MoveRequest { target, speed, zone, tool: Pose::identity(), held_object: None, wobj: Pose::identity() }
    }

    fn six(q: &Joints7) -> [f64; 6] {
        [q[0], q[1], q[2], q[3], q[4], q[5]]
    }

    #[test]
    fn a_joint_move_takes_axis_7_along() {
        let model = find_model("ROB_L_14000_05_05").unwrap();
        let kin = model.kinematics();
        let home = calibration(Side::Left);
        let goal: Joints7 = [20.0, -100.0, 10.0, 30.0, 60.0, -20.0, 90.0];
        let mut planner = Planner::new(six(&home), AccelLimits::nominal(&model.max_speeds));
        let ext = axis7_move(home[6], goal[6]);
        let mut moves: Vec<_> =
            planner.push_with(&kin, &request(Target::Joints(six(&goal))), Some(&ext)).unwrap().into_iter().collect();
        moves.extend(planner.flush());
        let last = moves.last().unwrap();
        assert_eq!(last.eax_end().unwrap()[0], 90.0);
        // Axis 7 moves 45°, at most 180°/s: the move takes at least 0.25 s.
        assert!(last.end - moves[0].start >= 0.25);
        // Every sample's flange is where its seven axes put it.
        for sample in moves.iter().flat_map(|m| m.samples(&kin, DEFAULT_STEP)) {
            let q7 =
                moves.iter().find_map(|m| (sample.time <= m.end).then(|| m.eax_at(sample.time))).flatten().unwrap()[0];
            let j = sample.joints;
            let fk = forward(Side::Left, &[j[0], j[1], j[2], j[3], j[4], j[5], q7]);
            assert!((fk.translation.vector - sample.flange.translation.vector).norm() < 1e-9);
        }
        let end = last.sample(&kin, last.end);
        assert!((end.flange.translation.vector - forward(Side::Left, &goal).translation.vector).norm() < 1e-9);
        assert!(kin.redundant());
    }

    #[test]
    fn a_linear_move_keeps_to_its_line_and_ends_at_the_arm_angle() {
        let model = find_model("ROB_R_14000_05_05").unwrap();
        let kin = model.kinematics();
        let start: Joints7 = [10.0, -110.0, 20.0, 10.0, 50.0, 10.0, -100.0];
        let goal: Joints7 = [25.0, -95.0, 5.0, 20.0, 55.0, 0.0, -80.0];
        let (p0, p1) = (forward(Side::Right, &start), forward(Side::Right, &goal));
        let mut planner = Planner::new(six(&start), AccelLimits::nominal(&model.max_speeds));
        planner.set_eax(Some([start[6]; 6]));
        let ext = axis7_move(start[6], goal[6]);
        let mut moves: Vec<_> =
            planner.push_with(&kin, &request(Target::Linear(p1)), Some(&ext)).unwrap().into_iter().collect();
        moves.extend(planner.flush());
        let m = moves.last().unwrap();
        let line = p1.translation.vector - p0.translation.vector;
        for sample in m.samples(&kin, DEFAULT_STEP) {
            let q7 = m.eax_at(sample.time).unwrap()[0];
            let j = sample.joints;
            let fk = forward(Side::Right, &[j[0], j[1], j[2], j[3], j[4], j[5], q7]);
            // The solved axes put the flange on the path, and the path is the line.
            assert!((fk.translation.vector - sample.flange.translation.vector).norm() < 1e-4, "{}", sample.time);
            let off = sample.flange.translation.vector - p0.translation.vector;
            assert!(off.cross(&line).norm() / line.norm() < 1e-6);
        }
        let end = m.sample(&kin, m.end);
        assert!((end.flange.translation.vector - p1.translation.vector).norm() < 1e-5);
        let j = end.joints;
        let reached = arm_angle(Side::Right, &[j[0], j[1], j[2], j[3], j[4], j[5], -80.0]);
        assert!((reached - arm_angle(Side::Right, &goal)).abs() < 1e-5, "{reached}");
    }

    #[test]
    fn the_elbow_turns_about_a_standing_tcp() {
        // Same TCP pose, axis 7 from −100° to −92°: the TCP stands (to the IK's tolerance)
        // while the arm's other axes follow axis 7, and the move takes at least 8° at
        // 180°/s = 1/22.5 s.
        let model = find_model("ROB_R_14000_05_05").unwrap();
        let kin = model.kinematics();
        let start: Joints7 = [10.0, -110.0, 20.0, 10.0, 50.0, 10.0, -100.0];
        let here = forward(Side::Right, &start);
        let mut planner = Planner::new(six(&start), AccelLimits::nominal(&model.max_speeds));
        planner.set_eax(Some([start[6]; 6]));
        let ext = axis7_move(start[6], -92.0);
        let mut moves: Vec<_> =
            planner.push_with(&kin, &request(Target::Linear(here)), Some(&ext)).unwrap().into_iter().collect();
        moves.extend(planner.flush());
        let m = moves.last().unwrap();
        assert!(m.end - m.start >= 8.0 / 180.0, "{}", m.end - m.start);
        let mut turned = 0.0f64;
        for sample in m.samples(&kin, DEFAULT_STEP) {
            let q7 = m.eax_at(sample.time).unwrap()[0];
            let j = sample.joints;
            let fk = forward(Side::Right, &[j[0], j[1], j[2], j[3], j[4], j[5], q7]);
            assert!((fk.translation.vector - here.translation.vector).norm() < 1e-4, "{}", sample.time);
            assert!(fk.rotation.angle_to(&here.rotation) < 1e-6);
            turned = turned.max((j[0] - start[0]).abs());
        }
        assert!(turned > 0.1, "axis 1 follows the elbow: {turned}");
        let end = m.sample(&kin, m.end);
        assert_eq!(m.eax_end().unwrap()[0], -92.0);
        assert!((end.joints[0] - start[0]).abs() > 0.1);
    }
}
