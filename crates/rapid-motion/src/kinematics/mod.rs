//! Forward and inverse kinematics of 6-axis arms with an ortho-parallel base and a
//! spherical wrist (OPW: Brandstötter, Angerer, Hofbaur 2014), in ABB's joint
//! convention: zero has the lower arm upright and the upper arm horizontal, and the
//! flange frame is ABB's `tool0`.
//!
//! The solver is our own closed form (`solve.rs`); `turns.rs` maps its principal
//! angles onto the multi-turn ranges of axes such as ±400° on axis 6. The 4-axis
//! palletizers (`pallet.rs`) answer the same interface, axes 4 and 5 held at 0. The
//! IRB 14000 YuMi's 7-axis arms (`yumi.rs`) have their own, numeric, kinematics.

mod pallet;
mod solve;
mod turns;
pub mod yumi;

use nalgebra::{Translation3, UnitQuaternion, Vector3};

use crate::{Joints, Kinematics, MotionError, Pose};

pub use pallet::PalletParams;
pub use solve::Branches;
pub use turns::{nearest_within_limits, LIMIT_TOLERANCE};

pub(crate) use turns::{turns as turns_of, Turns};

/// OPW link lengths in mm (motion.md §2.1): `a1` shoulder offset, `a2` elbow offset
/// (negative when the forearm axis lies above axis 3), `b` lateral offset, `c1` height
/// of axis 2, `c2` lower arm, `c3` upper arm to the wrist centre, `c4` wrist centre to
/// flange.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpwParams {
    pub a1: f64,
    pub a2: f64,
    pub b: f64,
    pub c1: f64,
    pub c2: f64,
    pub c3: f64,
    pub c4: f64,
}

/// An OPW arm (or a 4-axis palletizer, or an arm of the YuMi) with its joint limits
/// and axis speeds: the kinematics the VM asks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Opw {
    params: OpwParams,
    /// A palletizer's geometry; `params` is then unused.
    pallet: Option<PalletParams>,
    /// A YuMi arm; `params` is then unused.
    yumi: Option<Seventh>,
    limits: [(f64, f64); 6],
    speeds: [f64; 6],
}

/// A YuMi arm behind the 6-axis interface: its axes 1..6 are the interface's joints,
/// axis 7 rides in the external axes' `eax_a` (as in RAPID's jointtarget). Calls that
/// pass the external axes ([`Kinematics::forward_at`]) take axis 7 from them; the
/// others take it where it stands, `axis7`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seventh {
    pub side: yumi::Side,
    /// Axis 7 where the arm stands (the end of its last move), degrees.
    pub axis7: f64,
}

impl Seventh {
    /// The seven axes: `joints` with axis 7 from `eax_a`, or where it stands when
    /// `eax_a` is unused (9E9) or not given.
    pub fn joints7(&self, joints: &Joints, eax: Option<&crate::external::Eax>) -> yumi::Joints7 {
        let q7 = eax.map(|e| e[0]).filter(|q| !crate::external::is_unused(*q)).unwrap_or(self.axis7);
        [joints[0], joints[1], joints[2], joints[3], joints[4], joints[5], q7]
    }

    fn forward(&self, joints: &Joints, eax: Option<&crate::external::Eax>) -> Pose {
        yumi::forward(self.side, &self.joints7(joints, eax))
    }

    fn inverse_near(
        &self,
        flange: &Pose,
        seed: &Joints,
        eax: Option<&crate::external::Eax>,
    ) -> Result<Joints, MotionError> {
        let q7 = self.joints7(seed, eax)[6];
        yumi::inverse_locked(self.side, flange, q7, seed)
    }
}

/// A kinematics with the external axes standing at `eax`: what the planner hands its
/// path code for a 7-axis arm, whose axis 7 moves with the path in `eax_a`.
pub(crate) struct AtAxes<'a, K: ?Sized> {
    pub(crate) kin: &'a K,
    pub(crate) eax: crate::external::Eax,
}

impl<K: Kinematics + ?Sized> Kinematics for AtAxes<'_, K> {
    fn forward(&self, joints: &Joints) -> Pose {
        self.kin.forward_at(joints, &self.eax)
    }

    fn inverse(&self, flange: &Pose) -> Vec<Joints> {
        self.kin.inverse(flange)
    }

    fn limits(&self) -> [(f64, f64); 6] {
        self.kin.limits()
    }

    fn max_speeds(&self) -> [f64; 6] {
        self.kin.max_speeds()
    }

    fn inverse_near(&self, flange: &Pose, seed: &Joints) -> Result<Joints, MotionError> {
        self.kin.inverse_near_at(flange, seed, &self.eax)
    }
}

impl Opw {
    pub fn new(params: OpwParams, limits: [(f64, f64); 6], speeds: [f64; 6]) -> Opw {
        Opw { params, pallet: None, yumi: None, limits, speeds }
    }

    /// A 4-axis palletizer: axes 1, 2, 3 and 6; the limits of axes 4 and 5 are 0.
    pub fn palletizer(pallet: PalletParams, limits: [(f64, f64); 6], speeds: [f64; 6]) -> Opw {
        let zero = OpwParams { a1: 0.0, a2: 0.0, b: 0.0, c1: 0.0, c2: 0.0, c3: 0.0, c4: 0.0 };
        Opw { params: zero, pallet: Some(pallet), yumi: None, limits, speeds }
    }

    /// An arm of the YuMi (limits and speeds of axes 1..6), axis 7 standing at its
    /// calibration value.
    pub fn yumi(side: yumi::Side, limits: [(f64, f64); 6], speeds: [f64; 6]) -> Opw {
        let zero = OpwParams { a1: 0.0, a2: 0.0, b: 0.0, c1: 0.0, c2: 0.0, c3: 0.0, c4: 0.0 };
        let axis7 = yumi::calibration(side)[6];
        Opw { params: zero, pallet: None, yumi: Some(Seventh { side, axis7 }), limits, speeds }
    }

    /// A YuMi arm's side and where its axis 7 stands; `None` for a 6-axis arm.
    pub fn seventh(&self) -> Option<&Seventh> {
        self.yumi.as_ref()
    }

    /// The same YuMi arm with axis 7 standing at `q7` (no change for other arms).
    pub fn with_axis7(self, q7: f64) -> Opw {
        match self.yumi {
            Some(arm) if q7.is_finite() => Opw { yumi: Some(Seventh { axis7: q7, ..arm }), ..self },
            _ => self,
        }
    }

    /// The palletizer's geometry, for a 4-axis palletizer.
    pub fn pallet(&self) -> Option<&PalletParams> {
        self.pallet.as_ref()
    }

    /// The same arm with other joint limits (a backup's MOC.cfg `ARM` bounds, in degrees).
    pub fn with_limits(self, limits: [(f64, f64); 6]) -> Opw {
        Opw { limits, ..self }
    }

    pub fn params(&self) -> &OpwParams {
        &self.params
    }

    pub(crate) fn limits_ref(&self) -> &[(f64, f64); 6] {
        &self.limits
    }

    /// The eight arm/wrist solutions for a flange pose, indexed by cfx (bit 2: wrist
    /// centre behind axis 1, bit 1: behind the lower arm, bit 0: axis 5 negative), each
    /// with angles in (−180°, 180°] and joint limits not applied. Where an axis is free
    /// (wrist or shoulder singularity) it keeps the seed's value, or 0 without a seed.
    pub fn branches(&self, flange: &Pose, seed: Option<&Joints>) -> Branches {
        // A seed that is not a number cannot guide a free axis; free axes then take 0.
        let seed = seed.filter(|s| s.iter().all(|q| q.is_finite()));
        if let Some(arm) = &self.yumi {
            // A 7-axis arm has no eight branches: the one nearest the seed stands for them.
            let mut branches = [None; 8];
            branches[0] = arm.inverse_near(flange, seed.unwrap_or(&[0.0; 6]), None).ok();
            return branches;
        }
        match &self.pallet {
            Some(pallet) => pallet::branches(pallet, flange, seed),
            None => solve::branches(&self.params, flange, seed),
        }
    }

    /// cfx of a palletizer's joints (`confdata_of`).
    pub(crate) fn pallet_cfx(&self, joints: &Joints) -> Option<i32> {
        self.pallet.as_ref().map(|p| pallet::cfx(p, joints))
    }

    /// The 1-based axis of the first joint outside its limits, if any.
    pub fn limit_violation(&self, joints: &Joints) -> Option<usize> {
        joints.iter().zip(&self.limits).position(|(q, &(lo, hi))| !turns::within(*q, lo, hi)).map(|i| i + 1)
    }

    /// The wrist centre (axis 4/5/6 crossing) in the base frame for these joints, mm.
    pub fn wrist_centre(&self, joints: &Joints) -> Vector3<f64> {
        let p = &self.params;
        let [q1, q2, q3, ..] = joints.map(f64::to_radians);
        let t = q2 + q3;
        let x1 = p.a1 + p.c2 * q2.sin() + p.c3 * t.cos() - p.a2 * t.sin();
        let z1 = p.c1 + p.c2 * q2.cos() - p.c3 * t.sin() - p.a2 * t.cos();
        let (s1, c1) = q1.sin_cos();
        Vector3::new(x1 * c1 - p.b * s1, x1 * s1 + p.b * c1, z1)
    }
}

impl Kinematics for Opw {
    fn forward(&self, joints: &Joints) -> Pose {
        if let Some(arm) = &self.yumi {
            return arm.forward(joints, None);
        }
        if let Some(pallet) = &self.pallet {
            return pallet::forward(pallet, joints);
        }
        let [q1, q2, q3, q4, q5, q6] = joints.map(f64::to_radians);
        let y = Vector3::y_axis();
        let z = Vector3::z_axis();
        // The upper arm points along the wrist's z when q2 + q3 = −90°, hence the quarter turn.
        let rotation = UnitQuaternion::from_axis_angle(&z, q1)
            * UnitQuaternion::from_axis_angle(&y, q2 + q3 + std::f64::consts::FRAC_PI_2)
            * UnitQuaternion::from_axis_angle(&z, q4)
            * UnitQuaternion::from_axis_angle(&y, q5)
            * UnitQuaternion::from_axis_angle(&z, q6);
        let flange = self.wrist_centre(joints) + rotation * Vector3::new(0.0, 0.0, self.params.c4);
        Pose::from_parts(Translation3::from(flange), rotation)
    }

    fn inverse(&self, flange: &Pose) -> Vec<Joints> {
        if let Some(arm) = &self.yumi {
            return arm.inverse_near(flange, &[0.0; 6], None).into_iter().collect();
        }
        let mut res = Vec::new();
        for solution in self.branches(flange, None).iter().flatten() {
            turns::push_all_within(&mut res, solution, &self.limits);
        }
        res
    }

    fn limits(&self) -> [(f64, f64); 6] {
        self.limits
    }

    fn max_speeds(&self) -> [f64; 6] {
        self.speeds
    }

    /// The solution whose largest single-axis move from `seed` is smallest, choosing
    /// among the turns of axes with ranges beyond ±180° as well; free axes at a
    /// singularity keep the seed's value. `OutOfReach` when the pose has no solution at
    /// all, `JointLimit` when every solution leaves the limits.
    fn inverse_near(&self, flange: &Pose, seed: &Joints) -> Result<Joints, MotionError> {
        let seed = finite_seed(seed);
        if let Some(arm) = &self.yumi {
            return arm.inverse_near(flange, &seed, None);
        }
        if self.pallet.is_none() {
            if let Some(joints) = solve::seeded(&self.params, flange, &seed, &self.limits) {
                return Ok(joints);
            }
        }
        let branches = self.branches(flange, Some(&seed));
        nearest_within_limits(&branches, &seed, &self.limits)
    }

    fn forward_at(&self, joints: &Joints, eax: &crate::external::Eax) -> Pose {
        match &self.yumi {
            Some(arm) => arm.forward(joints, Some(eax)),
            None => self.forward(joints),
        }
    }

    fn inverse_near_at(&self, flange: &Pose, seed: &Joints, eax: &crate::external::Eax) -> Result<Joints, MotionError> {
        match &self.yumi {
            Some(arm) => arm.inverse_near(flange, &finite_seed(seed), Some(eax)),
            None => self.inverse_near(flange, seed),
        }
    }

    fn redundant(&self) -> bool {
        self.yumi.is_some()
    }
}

/// `x.rem_euclid(m)` (for `m > 0`), without fmod when `x` is less than one `m` from
/// zero, which is nearly always: the same bits, since fmod is exact there. The
/// inverse kinematics wraps some thirty angles per solution.
#[inline]
pub(crate) fn wrap(x: f64, m: f64) -> f64 {
    if (0.0..m).contains(&x) {
        x
    } else if x < 0.0 && x > -m {
        x + m
    } else {
        x.rem_euclid(m)
    }
}

/// The seed with any value that is not a number read as 0°, so comparisons with it
/// stay meaningful.
pub(crate) fn finite_seed(seed: &Joints) -> Joints {
    seed.map(|q| if q.is_finite() { q } else { 0.0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An arm with every OPW length non-zero, the lateral offset `b` included (no
    /// built-in ABB model has one).
    fn offset_arm() -> Opw {
        let params = OpwParams { a1: 120.0, a2: -60.0, b: 40.0, c1: 400.0, c2: 500.0, c3: 450.0, c4: 90.0 };
        let limits =
            [(-180.0, 180.0), (-120.0, 120.0), (-180.0, 120.0), (-400.0, 400.0), (-125.0, 125.0), (-400.0, 400.0)];
        Opw::new(params, limits, [100.0; 6])
    }

    #[test]
    fn zero_position_of_an_offset_arm() {
        // x = a1 + c3 + c4, y = b, z = c1 + c2 − a2; tool0 turned 90° about y.
        let flange = offset_arm().forward(&[0.0; 6]);
        assert!((flange.translation.vector - Vector3::new(660.0, 40.0, 960.0)).norm() < 1e-9);
    }

    #[test]
    fn offset_arm_round_trips() {
        let kin = offset_arm();
        let sets = [
            [10.0, 20.0, -30.0, 40.0, 50.0, 60.0],
            [-150.0, -60.0, 80.0, -200.0, -20.0, 300.0],
            [95.0, 100.0, -170.0, 5.0, 110.0, -5.0],
        ];
        for joints in sets {
            let flange = kin.forward(&joints);
            let got = kin.inverse_near(&flange, &joints).unwrap();
            assert!(got.iter().zip(&joints).all(|(a, b)| (a - b).abs() < 1e-6), "{got:?} for {joints:?}");
            for solution in kin.branches(&flange, None).iter().flatten() {
                let back = kin.forward(solution);
                assert!((back.translation.vector - flange.translation.vector).norm() < 1e-6);
                assert!(back.rotation.angle_to(&flange.rotation) < 1e-9);
            }
        }
    }

    #[test]
    fn wrap_gives_the_bits_rem_euclid_gives() {
        let m = 360.0;
        let xs =
            [0.0, -0.0, 1e-300, -1e-300, 359.999_999_999_999_94, -359.999_999_999_999_94, 360.0, -360.0, 725.5, -725.5];
        for x in xs.into_iter().chain((-2000..2000).map(|i| i as f64 * 0.731)) {
            assert_eq!(wrap(x, m).to_bits(), x.rem_euclid(m).to_bits(), "{x}");
        }
        assert!(wrap(f64::NAN, m).is_nan());
        let tau = std::f64::consts::TAU;
        for x in (-400..400).map(|i| i as f64 * 0.0173) {
            assert_eq!(wrap(x, tau).to_bits(), x.rem_euclid(tau).to_bits(), "{x}");
        }
    }

    /// The seeded shortcut must answer exactly what the search over all branches does,
    /// for seeds near and far from the solution and near every singularity.
    #[test]
    fn the_seeded_branch_answers_as_the_full_search_does() {
        let arms =
            [offset_arm(), crate::default_model().kinematics(), crate::find_model("IRB 6700").unwrap().kinematics()];
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut shortcuts = 0;
        for kin in &arms {
            let limits = kin.limits();
            for k in 0..20_000 {
                let mut joints: Joints = std::array::from_fn(|i| limits[i].0 + next() * (limits[i].1 - limits[i].0));
                // Every fourth set sits near the wrist singularity (axis 5 near 0).
                if k % 4 == 0 {
                    joints[4] = (next() - 0.5) * 1e-3;
                }
                let spread = [0.01, 1.0, 10.0, 90.0][k % 4];
                let seed: Joints = std::array::from_fn(|i| joints[i] + (next() - 0.5) * spread);
                let flange = kin.forward(&joints);
                let full = nearest_within_limits(&kin.branches(&flange, Some(&seed)), &seed, &limits);
                if solve::seeded(&kin.params, &flange, &seed, &limits).is_some() {
                    shortcuts += 1;
                }
                assert_eq!(kin.inverse_near(&flange, &seed), full, "joints {joints:?} seed {seed:?}");
            }
        }
        // The shortcut must actually be taken on most close seeds.
        assert!(shortcuts > 30_000, "{shortcuts}");
    }
}
