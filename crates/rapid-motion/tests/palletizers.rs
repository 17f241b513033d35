//! The 4-axis palletizers (IRB 260, 460, 660, 760): forward kinematics against
//! hand-worked tables, the flange kept level, inverse kinematics round trips, the
//! configuration and the refusal of orientations the linkage cannot take.
//!
//! Link lengths (mm, robots.rs): IRB 460 d1 = 745 (axis 2 height), a1 = 260, l2 = 945
//! (lower arm), l3 = 1025 (upper arm), a4 = 225, d5 = 251.5 (flange offset and drop).
//! The flange: reach r = a1 + l2·sin q2 + l3·cos q3 + a4 along the arm's heading q1,
//! height z = d1 + l2·cos q2 − l3·sin q3 − d5; tool0 turned 180° about y, then by
//! q1 − q6 about the base's z.

use nalgebra::{UnitQuaternion, Vector3};
use rapid_motion::pose::{orient, pose, trans};
use rapid_motion::robots::{find_model, palletizers};
use rapid_motion::{confdata_of, inverse_conf, ConfMatch, Joints, Kinematics, MotionError};

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= tol)
}

fn quat_close(a: [f64; 4], b: [f64; 4]) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-6)
}

#[test]
fn irb460_forward_matches_the_hand_worked_table() {
    let kin = find_model("IRB 460").expect("IRB 460").kinematics();
    let h = std::f64::consts::FRAC_1_SQRT_2;
    #[rustfmt::skip]
    let table: [(Joints, [f64; 3], [f64; 4]); 6] = [
        // Zero: r = 260 + 1025 + 225 = 1510, z = 745 + 945 − 251.5 = 1438.5; tool0
        // pointing down, x backwards: [0, 0, 1, 0] (the catalogue's DH product at zero
        // gives the same: rotation diag(−1, 1, −1)).
        ([0.0; 6], [1510.0, 0.0, 1438.5], [0.0, 0.0, 1.0, 0.0]),
        // Axis 1 at 90° turns it about z onto y; tool0's x then points along −y:
        // 180° about (1, −1, 0)/√2 = [0, h, −h, 0].
        ([90.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.0, 1510.0, 1438.5], [0.0, h, -h, 0.0]),
        // Axis 6 at 90° turns the flange about its own z (the base's −z): heading −90°,
        // tool0's x along +y: 180° about (1, 1, 0)/√2 = [0, h, h, 0]; the position stays.
        ([0.0, 0.0, 0.0, 0.0, 0.0, 90.0], [1510.0, 0.0, 1438.5], [0.0, h, h, 0.0]),
        // Axis 2 at 30°: r = 260 + 945·0.5 + 1025 + 225 = 1982.5,
        // z = 745 + 945·0.866025 − 251.5 = 1311.894; the flange stays level.
        ([0.0, 30.0, 0.0, 0.0, 0.0, 0.0], [1982.5, 0.0, 1311.894], [0.0, 0.0, 1.0, 0.0]),
        // Axis 3 at 30° (the upper arm 30° below level, axis 2 upright):
        // r = 260 + 1025·0.866025 + 225 = 1372.676, z = 745 + 945 − 512.5 − 251.5 = 926.
        ([0.0, 0.0, 30.0, 0.0, 0.0, 0.0], [1372.676, 0.0, 926.0], [0.0, 0.0, 1.0, 0.0]),
        // q = (−45, 40, 60, 0, 0, 0): r = 260 + 945·0.642788 + 1025·0.5 + 225 = 1604.934,
        // x = −y = r·0.707107 = 1134.860; z = 745 + 945·0.766044 − 1025·0.866025 − 251.5
        // = 745 + 723.912 − 887.676 − 251.5 = 329.736. Heading −45°: tool0's x
        // (−cos −45°, −sin −45°, 0) points at 135°; a half turn about a level axis at α
        // carries x to 2α, so α = 67.5°: [0, cos 67.5°, sin 67.5°, 0].
        ([-45.0, 40.0, 60.0, 0.0, 0.0, 0.0], [1134.860, -1134.860, 329.736],
         [0.0, 0.382683, 0.923880, 0.0]),
    ];
    for (joints, position, quaternion) in table {
        let flange = kin.forward(&joints);
        assert!(close(trans(&flange), position, 0.001), "{joints:?}: {:?}", trans(&flange));
        assert!(quat_close(orient(&flange), quaternion), "{joints:?}: {:?}", orient(&flange));
    }
}

#[test]
fn every_palletizer_at_zero_and_stretched_out_matches_its_data_sheet() {
    // At zero: (a1 + l3 + a4, 0, d1 + l2 − d5), pointing down. Stretched out (axis 2 at
    // its forward limit, the upper arm level) the flange is about the reach the
    // product name gives (2.4 m for the IRB 460, 3.15 m for the IRB 660, …), within 3 %
    // (where the data sheet measures its reach from is not given to us).
    #[rustfmt::skip]
    let table = [
        // name, zero x, zero z, axis 2 forward limit, named reach (mm)
        ("IRB 260-30/1.53", 100.0 + 650.0 + 120.0, 615.0 + 705.0 - 181.0, 85.0, 1530.0),
        ("IRB 460-110/2.4", 260.0 + 1025.0 + 225.0, 745.0 + 945.0 - 251.5, 85.0, 2400.0),
        ("IRB 660-180/3.15", 300.0 + 1350.0 + 260.0, 800.0 + 1280.0 - 247.0, 82.0, 3150.0),
        ("IRB 660-250/3.15", 300.0 + 1350.0 + 260.0, 800.0 + 1280.0 - 247.0, 82.0, 3150.0),
        ("IRB 760-450/3.18", 300.0 + 1350.0 + 290.0, 814.5 + 1280.0 - 269.0, 82.0, 3180.0),
    ];
    assert_eq!(table.len(), palletizers().len());
    for (name, x, z, forward, reach) in table {
        let model = find_model(name).unwrap_or_else(|| panic!("no {name}"));
        assert_eq!(model.name, name);
        assert!(model.is_palletizer());
        let kin = model.kinematics();
        let flange = kin.forward(&[0.0; 6]);
        assert!(close(trans(&flange), [x, 0.0, z], 1e-9), "{name}: {:?}", trans(&flange));
        assert!(quat_close(orient(&flange), [0.0, 0.0, 1.0, 0.0]), "{name}");
        let out = trans(&kin.forward(&[0.0, forward, 0.0, 0.0, 0.0, 0.0]))[0];
        assert!((out - reach).abs() < 0.03 * reach, "{name}: stretched out to {out}");
        // A turn of axis 1 by 90° carries the zero position onto y.
        let turned = trans(&kin.forward(&[90.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
        assert!(close(turned, [0.0, x, z], 1e-9), "{name}: {turned:?}");
    }
}

/// xorshift64*: a fixed sequence of test joints.
fn next(state: &mut u64) -> f64 {
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
}

#[test]
fn palletizers_solve_back_to_their_joints() {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    for model in palletizers() {
        let kin = model.kinematics();
        let limits = kin.limits();
        for _ in 0..2000 {
            let joints: Joints = std::array::from_fn(|i| limits[i].0 + (limits[i].1 - limits[i].0) * next(&mut state));
            let flange = kin.forward(&joints);
            let near = kin.inverse_near(&flange, &joints).expect("reachable");
            assert!(near.iter().zip(&joints).all(|(a, b)| (a - b).abs() < 1e-6), "{near:?} for {joints:?}");
            let conf = confdata_of(&kin, &joints);
            assert_eq!((conf[1], conf[3] & 1), (0, 0), "axis 4 is 0, axis 5 never negative");
            let by_conf = inverse_conf(&kin, &flange, &conf, &[0.0; 6], ConfMatch::Exact).expect("by conf");
            assert!(by_conf.iter().zip(&joints).all(|(a, b)| (a - b).abs() < 1e-6), "{by_conf:?} for {joints:?}");
            for s in kin.inverse(&flange) {
                let back = kin.forward(&s);
                assert!((back.translation.vector - flange.translation.vector).norm() < 1e-6);
                assert!(back.rotation.angle_to(&flange.rotation) < 1e-9);
            }
        }
    }
}

#[test]
fn a_palletizer_cannot_tilt_its_flange() {
    let kin = find_model("IRB 660-180/3.15").expect("IRB 660").kinematics();
    let level = kin.forward(&[10.0, 20.0, 30.0, 0.0, 0.0, 40.0]);
    // Tilted 1° about x: no solution, out of reach.
    let tilt = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 1f64.to_radians());
    let tilted = nalgebra::Isometry3::from_parts(level.translation, level.rotation * tilt);
    assert!(kin.inverse(&tilted).is_empty());
    assert_eq!(kin.inverse_near(&tilted, &[0.0; 6]), Err(MotionError::OutOfReach));
    // Farther than the arms reach: out of reach too.
    let far = pose([4000.0, 0.0, 1000.0], [0.0, 0.0, 1.0, 0.0]);
    assert_eq!(kin.inverse_near(&far, &[0.0; 6]), Err(MotionError::OutOfReach));
}
