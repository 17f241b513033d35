//! Kinematics against public ground truth (motion.md §5: the IRB 120 joint → pose
//! vectors, the IRB 4600-20/2.50 table, calibration positions), FK∘IK round trips on
//! every built-in model, confdata selection and the controller's errors.

use nalgebra::UnitQuaternion;
use rapid_motion::kinematics::Opw;
use rapid_motion::pose::{orient, pose, trans};
use rapid_motion::{confdata_of, find_model, inverse_conf, models, ConfMatch, Joints, Kinematics, MotionError, Pose};

fn model(name: &str) -> Opw {
    find_model(name).unwrap_or_else(|| panic!("no model {name}")).kinematics()
}

/// The rotation of ABB's EulerZYX angles (degrees): Rz(z)·Ry(y)·Rx(x) (motion.md §3.4).
fn euler_zyx(z: f64, y: f64, x: f64) -> UnitQuaternion<f64> {
    UnitQuaternion::from_euler_angles(x.to_radians(), y.to_radians(), z.to_radians())
}

fn assert_position(pose: &Pose, expected: [f64; 3], tol: f64) {
    let got = trans(pose);
    let off = got.iter().zip(&expected).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    assert!(off <= tol, "position {got:?}, expected {expected:?}");
}

fn assert_joints(got: &Joints, expected: &Joints, tol: f64) {
    let off = got.iter().zip(expected).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    assert!(off <= tol, "joints {got:?}, expected {expected:?} (off by {off:e})");
}

fn same_pose(a: &Pose, b: &Pose) -> bool {
    (a.translation.vector - b.translation.vector).norm() < 1e-6 && a.rotation.angle_to(&b.rotation) < 1e-9
}

#[test]
fn irb120_forward_matches_the_public_vectors() {
    let kin = model("IRB 120-3/0.58");
    // motion.md §5 item 3: joints → position (mm) and EulerZYX z, y, x (degrees), given
    // to 0.001.
    #[rustfmt::skip]
    let table: [([f64; 6], [f64; 3], [f64; 3]); 6] = [
        ([0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [374.0, 0.0, 630.0], [0.0, 90.0, 0.0]),
        ([30.0, -45.0, 20.0, 40.0, -30.0, 60.0], [96.492, 28.990, 723.337], [112.051, -18.032, 41.412]),
        ([-60.0, 35.0, -40.0, -70.0, 45.0, -120.0], [209.494, -458.536, 594.316], [-52.419, -74.149, 131.030]),
        ([90.0, -80.0, 50.0, 100.0, -60.0, 200.0], [61.407, -2.768, 557.130], [-50.859, 50.287, -79.197]),
        ([-120.0, 70.0, -70.0, 140.0, 80.0, -300.0], [-244.638, -514.881, 506.663], [110.979, -38.549, 15.287]),
        ([150.0, -100.0, 65.0, -150.0, -100.0, 350.0], [11.445, -47.546, 416.203], [165.873, -30.404, -157.744]),
    ];
    for (joints, position, [z, y, x]) in table {
        let flange = kin.forward(&joints);
        assert_position(&flange, position, 0.0015);
        // 0.001° rounding on each of three angles.
        let angle = flange.rotation.angle_to(&euler_zyx(z, y, x)).to_degrees();
        assert!(angle < 0.003, "{joints:?}: orientation off by {angle}°");
    }
    // Row 2's quaternion as ABB prints it.
    let o = orient(&kin.forward(&table[1].0));
    let expected = [0.470322, 0.316706, 0.207678, 0.797098];
    assert!(o.iter().zip(&expected).all(|(a, b)| (a - b).abs() < 2e-6), "{o:?}");
}

#[test]
fn irb4600_forward_matches_the_public_table() {
    let kin = model("IRB 4600-20/2.50");
    // motion.md §5 item 4, positions to 0.01 mm.
    assert_position(&kin.forward(&[0.0; 6]), [1490.5, 0.0, 1765.0], 1e-9);
    assert_position(&kin.forward(&[90.0, 0.0, 0.0, 0.0, 0.0, 0.0]), [0.0, 1490.5, 1765.0], 1e-9);
    assert_position(&kin.forward(&[45.0; 6]), [734.88, 794.99, -21.32], 0.006);
    assert_position(&kin.forward(&[-45.0; 6]), [-547.50, 607.60, 2559.89], 0.006);
}

#[test]
fn calibration_positions() {
    // motion.md §2.2 "tool0 at zero", orientation [0.707107, 0, 0.707107, 0] (§5 item 7).
    let table = [
        ("IRB 120-3/0.58", 374.0, 630.0),
        ("IRB 120T", 374.0, 630.0),
        ("IRB 140", 515.0, 712.0),
        ("IRB 1200-5/0.9", 533.0, 889.1),
        ("IRB 1200-7/0.7", 433.0, 791.1),
        ("IRB 1600-6/1.2", 815.0, 961.5),
        ("IRB 1600-10/1.45", 815.0, 1186.5),
        ("IRB 2400", 940.0, 1455.0),
        ("IRB 2600", 1030.0, 1260.0),
        ("IRB 4600-60/2.05", 1270.0, 1570.0),
        ("IRB 4600-40/2.55", 1580.0, 1765.0),
        ("IRB 4600-20/2.50", 1490.5, 1765.0),
        ("IRB 6640", 1912.0, 2055.0),
        ("IRB 6700-200/2.60", 1662.5, 2105.0),
        ("IRB 6700-235/2.65", 1702.5, 2115.0),
        ("IRB 7600", 2672.0, 2020.0),
    ];
    assert_eq!(table.len(), models().len());
    let h = std::f64::consts::FRAC_1_SQRT_2;
    for (name, x, z) in table {
        let flange = model(name).forward(&[0.0; 6]);
        assert_position(&flange, [x, 0.0, z], 1e-9);
        let o = orient(&flange);
        assert!((o[0] - h).abs() < 1e-12 && o[1].abs() < 1e-12 && (o[2] - h).abs() < 1e-12 && o[3].abs() < 1e-12);
    }
}

/// xorshift64*: a fixed, dependency-free sequence of test joints.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn joints(&mut self, limits: &[(f64, f64); 6]) -> Joints {
        std::array::from_fn(|i| limits[i].0 + (limits[i].1 - limits[i].0) * self.unit())
    }
}

#[test]
fn forward_inverse_round_trips_on_every_model() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for m in models() {
        let kin = m.kinematics();
        for _ in 0..1500 {
            let joints = rng.joints(&kin.limits());
            let flange = kin.forward(&joints);
            // Closest to the original: the original itself.
            let near = kin.inverse_near(&flange, &joints).unwrap();
            assert_joints(&near, &joints, 1e-6);
            // The programmed configuration alone (a seed far away) finds it too.
            let conf = confdata_of(&kin, &joints);
            let by_conf = inverse_conf(&kin, &flange, &conf, &[0.0; 6], ConfMatch::Exact).unwrap();
            assert_joints(&by_conf, &joints, 1e-6);
            // Every solution returned reaches the pose, within limits.
            let all = kin.inverse(&flange);
            assert!(all.iter().any(|s| s.iter().zip(&joints).all(|(a, b)| (a - b).abs() < 1e-6)));
            for s in &all {
                assert!(same_pose(&kin.forward(s), &flange), "{}: {s:?} for {joints:?}", m.name);
                assert!(kin.limit_violation(s).is_none());
            }
        }
    }
}

#[test]
fn all_eight_branches_reach_the_pose() {
    let kin = model("IRB 2400");
    let flange = kin.forward(&[20.0, 10.0, 15.0, 30.0, 40.0, 50.0]);
    let branches = kin.branches(&flange, None);
    for (cfx, branch) in branches.iter().enumerate() {
        let joints = branch.unwrap_or_else(|| panic!("branch {cfx} missing"));
        assert!(same_pose(&kin.forward(&joints), &flange), "branch {cfx}: {joints:?}");
        // Each branch is the configuration its index names.
        assert_eq!(confdata_of(&kin, &joints)[3], cfx as i32, "{joints:?}");
    }
}

#[test]
fn turns_of_axes_4_and_6_follow_seed_and_confdata() {
    let kin = model("IRB 4600-60/2.05");
    let flange = kin.forward(&[0.0, 0.0, 0.0, 10.0, 30.0, 20.0]);
    // The same pose with axis 4 and 6 one turn on (both ranges are ±400°).
    let turned = [0.0, 0.0, 0.0, 370.0, 30.0, 380.0];
    assert_joints(&kin.inverse_near(&flange, &turned).unwrap(), &turned, 1e-9);
    assert_joints(&kin.inverse_near(&flange, &[0.0; 6]).unwrap(), &[0.0, 0.0, 0.0, 10.0, 30.0, 20.0], 1e-9);
    let by_conf = inverse_conf(&kin, &flange, &[0, 4, -4, 0], &[0.0; 6], ConfMatch::Exact).unwrap();
    assert_joints(&by_conf, &[0.0, 0.0, 0.0, 370.0, 30.0, -340.0], 1e-9);
    // Axis 4 at 10° + 180° (the flipped wrist) is 190° or −170°; cfx 1 asks for it.
    let flipped = inverse_conf(&kin, &flange, &[0, -2, -2, 1], &[0.0; 6], ConfMatch::Exact).unwrap();
    assert_joints(&flipped, &[0.0, 0.0, 0.0, -170.0, -30.0, -160.0], 1e-9);
    // Nine turn combinations of the programmed branch are within ±400°.
    let all = kin.inverse(&flange);
    let same_arm = all.iter().filter(|s| s[..3].iter().all(|q| q.abs() < 1e-9) && (s[4] - 30.0).abs() < 1e-9);
    assert_eq!(same_arm.count(), 9);
}

#[test]
fn compliant_confdata_accepts_a_neighbouring_quadrant() {
    let kin = model("IRB 120");
    let joints = [10.0, 0.0, 0.0, 0.0, 30.0, -5.0];
    let flange = kin.forward(&joints);
    // cf6 = 0 asked, the solution has q6 = −5° (quadrant −1).
    let asked = [0, 0, 0, 0];
    assert_eq!(inverse_conf(&kin, &flange, &asked, &[0.0; 6], ConfMatch::Exact), Err(MotionError::Configuration));
    assert_joints(&inverse_conf(&kin, &flange, &asked, &[0.0; 6], ConfMatch::Compliant).unwrap(), &joints, 1e-9);
    // Two quadrants off is never accepted: the turns of q6 within ±400° are −365°, −5°
    // and 355°, in quadrants −5, −1 and 3.
    let far = [0, 0, 1, 0];
    assert_eq!(inverse_conf(&kin, &flange, &far, &[0.0; 6], ConfMatch::Compliant), Err(MotionError::Configuration));
}

#[test]
fn wrist_singularity_keeps_axis_4() {
    let kin = model("IRB 120");
    let flange = kin.forward(&[0.0, 10.0, 20.0, 30.0, 0.0, 40.0]);
    // Axes 4 and 6 are parallel at q5 = 0: only q4 + q6 = 70° is fixed.
    let got = kin.inverse_near(&flange, &[0.0, 10.0, 20.0, 25.0, 0.0, 0.0]).unwrap();
    assert_joints(&got, &[0.0, 10.0, 20.0, 25.0, 0.0, 45.0], 1e-9);
    let got = inverse_conf(&kin, &flange, &[0, 0, 0, 0], &[0.0; 6], ConfMatch::Exact).unwrap();
    assert_joints(&got, &[0.0, 10.0, 20.0, 0.0, 0.0, 70.0], 1e-9);
    // Asked for q4 in quadrant 1 and q6 in quadrant −1 from q4 = 0: q4 moves to the
    // quadrant's start, 90°, and q6 = 70° − 90° = −20°.
    let got = inverse_conf(&kin, &flange, &[0, 1, -1, 0], &[0.0; 6], ConfMatch::Exact).unwrap();
    assert_joints(&got, &[0.0, 10.0, 20.0, 90.0, 0.0, -20.0], 1e-9);
    // q4 in quadrant 1 and q6 in quadrant 1 cannot share 70° (or 70° ± 360°) within
    // q4's ±160°: q4 ∈ [90, 160] leaves q6 ∈ [−90, −20] or [270, 340].
    let got = inverse_conf(&kin, &flange, &[0, 1, 1, 0], &[0.0; 6], ConfMatch::Exact);
    assert_eq!(got, Err(MotionError::Configuration));
    for s in kin.inverse(&flange) {
        assert!(s.iter().all(|q| q.is_finite()) && same_pose(&kin.forward(&s), &flange));
    }
}

#[test]
fn shoulder_singularity_keeps_axis_1() {
    let kin = model("IRB 120");
    // Wrist centre on axis 1 (a1 = 0): 270·sin q2 + k·cos(q2 + q3 + φ) = 0 with
    // k = √(302² + 70²), φ = atan2(−70, 302). q2 = 10° gives q2 + q3 + φ = −98.7°, away
    // from the stretched arm (−90°), which is a singularity of its own.
    let k = 302.0f64.hypot(70.0);
    let phi = (-70.0f64).atan2(302.0).to_degrees();
    let q3 = -(-270.0 * 10.0f64.to_radians().sin() / k).acos().to_degrees() - phi - 10.0;
    let joints = [20.0, 10.0, q3, 10.0, 30.0, 0.0];
    let centre = kin.wrist_centre(&joints);
    assert!(centre.x.hypot(centre.y) < 1e-9, "{centre:?}");
    let flange = kin.forward(&joints);
    let got = kin.inverse_near(&flange, &joints).unwrap();
    assert!(same_pose(&kin.forward(&got), &flange), "{got:?}");
    assert_joints(&got, &joints, 1e-6);
}

#[test]
fn unreachable_poses_and_limits() {
    let kin = model("IRB 120");
    let far = pose([2000.0, 0.0, 300.0], [1.0, 0.0, 0.0, 0.0]);
    assert!(kin.inverse(&far).is_empty());
    assert_eq!(kin.inverse_near(&far, &[0.0; 6]), Err(MotionError::OutOfReach));
    assert_eq!(inverse_conf(&kin, &far, &[0, 0, 0, 0], &[0.0; 6], ConfMatch::Compliant), Err(MotionError::OutOfReach));
    // A pose with NaN in it has no solution and no NaN answer.
    let nan = pose([f64::NAN, 0.0, 300.0], [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(kin.inverse_near(&nan, &[0.0; 6]), Err(MotionError::OutOfReach));
    let zero_quat = pose([300.0, 0.0, 300.0], [0.0, 0.0, 0.0, 0.0]);
    assert_eq!(kin.inverse_near(&zero_quat, &[0.0; 6]), Err(MotionError::OutOfReach));
    // Axis 1 held to ±10°: a pose at q1 = 45° needs 45° (front) or −135° (behind).
    let narrow = {
        let mut limits = kin.limits();
        limits[0] = (-10.0, 10.0);
        kin.with_limits(limits)
    };
    let flange = kin.forward(&[45.0, 0.0, 0.0, 0.0, 30.0, 0.0]);
    assert_eq!(narrow.inverse_near(&flange, &[0.0; 6]), Err(MotionError::JointLimit { axis: 1 }));
    assert_eq!(
        inverse_conf(&narrow, &flange, &[0, 0, 0, 0], &[0.0; 6], ConfMatch::Exact),
        Err(MotionError::JointLimit { axis: 1 })
    );
}

#[test]
fn configuration_that_cannot_reach() {
    let kin = model("IRB 4600-60/2.05");
    // Lower arm horizontal and upper arm nearly in line: the wrist centre is about
    // 1860 mm in front of axis 2. Behind axis 1 it would be 2·a1 = 350 mm further, past
    // the arm's reach c2 + √(c3² + a2²) = 1875.8 mm.
    let joints = [0.0, 90.0, -70.0, 0.0, 30.0, 0.0];
    let flange = kin.forward(&joints);
    let conf = confdata_of(&kin, &joints);
    assert_eq!(conf, [0, 0, 0, 0]);
    assert_joints(&inverse_conf(&kin, &flange, &conf, &[0.0; 6], ConfMatch::Exact).unwrap(), &joints, 1e-6);
    for cfx in 4..8 {
        let asked = [0, 0, 0, cfx];
        assert_eq!(
            inverse_conf(&kin, &flange, &asked, &[0.0; 6], ConfMatch::Compliant),
            Err(MotionError::Configuration)
        );
    }
    assert_eq!(
        inverse_conf(&kin, &flange, &[0, 0, 0, 9], &[0.0; 6], ConfMatch::Compliant),
        Err(MotionError::Configuration)
    );
}

#[test]
fn stretched_arm_has_one_elbow_and_no_nan() {
    let kin = model("IRB 120");
    // q3 + φ = −90° with φ = atan2(−70, 302): the upper arm in line with the lower arm.
    let q3 = -90.0 - (-70.0f64).atan2(302.0).to_degrees();
    let joints = [0.0, 20.0, q3, 0.0, 40.0, 0.0];
    let flange = kin.forward(&joints);
    let branches = kin.branches(&flange, None);
    for joints in branches.iter().flatten() {
        assert!(joints.iter().all(|q| q.is_finite()));
        assert!((kin.forward(joints).translation.vector - flange.translation.vector).norm() < 1e-5);
    }
    // Both elbows coincide; near the stretched arm the angle is only good to about
    // √ε of the elbow cosine, hence the looser bound.
    let got = kin.inverse_near(&flange, &joints).unwrap();
    assert_joints(&got, &joints, 1e-4);
}

#[test]
fn seeds_that_are_not_numbers() {
    let kin = model("IRB 120");
    let joints = [0.0, 10.0, 20.0, 30.0, 0.0, 40.0];
    let flange = kin.forward(&joints);
    let seed = [f64::NAN; 6];
    let got = kin.inverse_near(&flange, &seed).unwrap();
    assert!(got.iter().all(|q| q.is_finite()) && same_pose(&kin.forward(&got), &flange));
    let got = inverse_conf(&kin, &flange, &[0, 0, 0, 0], &seed, ConfMatch::Exact).unwrap();
    assert_joints(&got, &[0.0, 10.0, 20.0, 0.0, 0.0, 70.0], 1e-9);
}

#[test]
fn calc_joint_t_and_calc_rob_t_through_tool_wobj_and_displacement() {
    use rapid_motion::FrameChain;
    let kin = model("IRB 1600-10/1.45");
    let chain = FrameChain {
        base: pose([0.0, 0.0, 200.0], [1.0, 0.0, 0.0, 0.0]),
        tframe: pose([10.0, 0.0, 150.0], [0.965926, 0.0, 0.258819, 0.0]),
        uframe: pose([900.0, -300.0, 100.0], [0.5, 0.0, 0.0, 0.5]),
        oframe: pose([50.0, 50.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
        pdisp: pose([5.0, -5.0, 10.0], [1.0, 0.0, 0.0, 0.0]),
        stationary_tool: false,
    };
    let joints = [-20.0, 30.0, 10.0, 40.0, 50.0, -60.0];
    // CalcRobT, then CalcJointT of its result, gives the joints back.
    let (target, conf) = chain.robtarget_of(&kin, &joints);
    let back = chain.joints_for(&kin, &target, &conf, &[0.0; 6], ConfMatch::Exact).unwrap();
    assert_joints(&back, &joints, 1e-6);
    // The TCP in the world is where the object frame puts the displaced target.
    let world = chain.tcp_in_world(&kin.forward(&joints));
    let via_object = chain.uframe * chain.oframe * chain.pdisp * target;
    assert!(same_pose(&world, &via_object));

    // The same with the robot holding the work object past a stationary tool.
    let held = FrameChain {
        tframe: pose([1200.0, 300.0, 600.0], [0.0, 0.0, 1.0, 0.0]),
        uframe: pose([0.0, 0.0, 120.0], [1.0, 0.0, 0.0, 0.0]),
        stationary_tool: true,
        ..chain
    };
    let (target, conf) = held.robtarget_of(&kin, &joints);
    let back = held.joints_for(&kin, &target, &conf, &[0.0; 6], ConfMatch::Exact).unwrap();
    assert_joints(&back, &joints, 1e-6);
}

/// A robtarget as a RAPID program holds it: `num` is single precision, so the pose
/// CRobT reports reaches the next move rounded to f32.
fn as_rapid_data(p: &Pose) -> Pose {
    let t = trans(p).map(|v| f64::from(v as f32));
    let o = orient(p).map(|v| f64::from(v as f32));
    pose(t, o)
}

/// Issue 20 item 6: `MoveJ CRobT(\Tool:=t \WObj:=w), v100, fine, t;` from the
/// calibration position (a wrist singularity, axis 5 at 0) must move nowhere, for every
/// model and for tools turned about any axis. Rounded to single precision, the pose is
/// no longer exactly singular: the solver's axis 4 and 6 then come from rounding noise,
/// and a configuration check against CRobT's cf4/cf6 used to fail (50080).
#[test]
fn crobt_at_the_wrist_singularity_moves_back() {
    use rapid_motion::FrameChain;
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let tools = [
        pose([0.0, 0.0, 100.0], [1.0, 0.0, 0.0, 0.0]),
        pose([0.0, 0.0, 100.0], [h, 0.0, 0.0, h]),
        pose([0.0, 0.0, 100.0], [h, 0.0, 0.0, -h]),
        pose([10.0, -20.0, 150.0], [0.5, 0.5, 0.5, 0.5]),
        pose([0.0, 0.0, 100.0], [0.0, 0.0, 0.0, 1.0]),
        pose([0.0, 0.0, 100.0], [0.866_025, 0.0, 0.5, 0.0]),
        pose([0.0, 0.0, 100.0], [0.923_880, 0.0, 0.0, -0.382_683]),
    ];
    // The calibration position, and q5 = 0 with axes 4 and 6 in other quadrants.
    let starts: [Joints; 3] =
        [[0.0; 6], [30.0, 10.0, 20.0, 45.0, 0.0, -100.0], [-20.0, 5.0, -10.0, -120.0, 0.0, 135.0]];
    for m in models() {
        let kin = m.kinematics();
        for tframe in tools {
            for start in starts {
                let chain = FrameChain { tframe, ..FrameChain::default() };
                let (target, conf) = chain.robtarget_of(&kin, &start);
                let target = as_rapid_data(&target);
                let got = chain
                    .joints_for(&kin, &target, &conf, &start, ConfMatch::Compliant)
                    .unwrap_or_else(|e| panic!("{}: {tframe:?} from {start:?} conf {conf:?}: {e}", m.name));
                // The move goes nowhere: every axis within rounding of where it is.
                assert_joints(&got, &start, 1e-2);
                assert_eq!(confdata_of(&kin, &got)[..3], conf[..3], "{}", m.name);
                // Exact configuration too (ConfJ\On with the reported configuration).
                chain.joints_for(&kin, &target, &conf, &start, ConfMatch::Exact).expect("exact");
            }
        }
    }
}
