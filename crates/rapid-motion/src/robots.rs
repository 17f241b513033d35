//! The built-in ABB robot models (OPW link lengths, joint limits, axis speeds) and the
//! lookup of a model by the names users and backups give it.
//!
//! Geometry, limits and speeds come from `shared/reference/motion.md` §2.2 and §2.3
//! (rs-opw-kinematics presets and the ROS-Industrial URDFs, cross-checked there).
//! Lengths are stored in millimetres.

use crate::kinematics::yumi::{self, Side};
use crate::kinematics::{Opw, OpwParams, PalletParams};

/// One robot variant: its name as ABB writes it, what its name may be written as,
/// its arm geometry and its axis data.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotModel {
    /// ABB's product name, e.g. `IRB 120-3/0.58`.
    pub name: &'static str,
    /// Family names this variant answers to (`120`, `140t`), lower case.
    families: &'static [&'static str],
    /// Handling capacities in kg that name this geometry (`IRB 4600-60/2.05` → 60).
    payloads: &'static [u32],
    /// Reaches in metres that name this geometry (`IRB 4600-60/2.05` → 2.05).
    reaches: &'static [f64],
    /// OPW link lengths, mm (unused for a palletizer).
    pub opw: OpwParams,
    /// A 4-axis palletizer's link lengths, mm.
    pub pallet: Option<PalletParams>,
    /// Lower and upper limit of each axis, degrees.
    pub limits: [(f64, f64); 6],
    /// Maximum speed of each axis, degrees per second.
    pub max_speeds: [f64; 6],
    /// The "max TCP velocity" of ABB's product specification, mm/s, where we have it;
    /// `None` where not (see [`RobotModel::tcp_speed`]).
    pub max_tcp_speed: Option<f64>,
    /// An arm of the IRB 14000 YuMi: a 7-axis arm whose axis 7 rides in `extax.eax_a`
    /// (`kinematics/yumi.rs`); `limits` and `max_speeds` are then those of axes 1..6.
    pub yumi: Option<Side>,
}

impl RobotModel {
    /// The highest TCP speed of the model, mm/s (MaxRobSpeed): the controller's
    /// configured figure where we have it, else a bound from the geometry: axes 1, 2
    /// and 3 at full speed with the arm stretched out horizontally, their TCP speeds
    /// added (the axes allow no more).
    // uncertain: the bound is ours and errs high: 7.3 m/s for the IRB 120 (configured
    // 6.2) and 11.8 m/s for the IRB 1200-5/0.9 (configured 8.4).
    pub fn tcp_speed(&self) -> f64 {
        if let Some(v) = self.max_tcp_speed {
            return v;
        }
        let radii = match &self.pallet {
            Some(p) => [p.a1 + p.l2 + p.l3 + p.a4, p.l2 + p.l3 + p.a4, p.l3 + p.a4],
            None => {
                let p = &self.opw;
                let lower = p.c2.hypot(p.a2);
                let wrist = p.c3 + p.c4;
                [p.a1 + lower + wrist, lower + wrist, wrist]
            }
        };
        radii.iter().zip(&self.max_speeds).map(|(r, w)| r * w.to_radians()).sum()
    }

    /// The kinematics of this model, with its nominal joint limits.
    pub fn kinematics(&self) -> Opw {
        match (self.pallet, self.yumi) {
            (_, Some(side)) => Opw::yumi(side, self.limits, self.max_speeds),
            (Some(pallet), None) => Opw::palletizer(pallet, self.limits, self.max_speeds),
            (None, None) => Opw::new(self.opw, self.limits, self.max_speeds),
        }
    }

    /// Where the robot stands when the system starts: its calibration position, all
    /// axes 0 (a YuMi arm's axes 1..6 of [`yumi::calibration`]).
    pub fn calibration(&self) -> crate::Joints {
        match self.yumi {
            Some(side) => {
                let q = yumi::calibration(side);
                [q[0], q[1], q[2], q[3], q[4], q[5]]
            }
            None => [0.0; 6],
        }
    }

    /// Whether the model is a 4-axis palletizer (axes 1, 2, 3 and 6).
    pub fn is_palletizer(&self) -> bool {
        self.pallet.is_some()
    }
}

/// The model a controller without other information runs: IRB 120-3/0.58.
pub fn default_model() -> &'static RobotModel {
    &MODELS[0]
}

/// Every built-in 6-axis arm, the default first, then by family.
pub fn models() -> &'static [RobotModel] {
    MODELS
}

/// The built-in 4-axis palletizers (IRB 260, 460, 660, 760).
pub fn palletizers() -> &'static [RobotModel] {
    PALLETIZERS
}

/// The two arms of the IRB 14000 YuMi (ROB_R, then ROB_L).
pub fn yumi_arms() -> &'static [RobotModel] {
    YUMI
}

/// Every built-in model: the 6-axis arms, the palletizers, then the YuMi's arms.
pub fn all_models() -> impl Iterator<Item = &'static RobotModel> {
    MODELS.iter().chain(PALLETIZERS).chain(YUMI)
}

/// The model a name stands for, or `None` when no built-in model fits.
///
/// Accepts what users and backups write: `IRB120`, `IRB 120-3/0.58`, `irb120_3_58`,
/// `irb4600_60_205`, and MOC.cfg robot types such as `ROB1_120_0.58`,
/// `ROB1_1200_0.9_5_TypeB` or `ROB1_6700_LeanID_2.65_220`, in any case and with any of
/// ` _-/,` between the parts. A bare family (`IRB 4600`) gives its first variant.
/// Numbers after the family pick the variant: a decimal is a reach in metres, an
/// integer a handling capacity in kg or a reach in centimetres (`58` for 0.58 m).
pub fn find_model(name: &str) -> Option<&'static RobotModel> {
    let parsed = ParsedName::of(name)?;
    if parsed.family == "14000" {
        return Some(yumi_arm(name));
    }
    let mut best: Option<(usize, &'static RobotModel)> = None;
    for model in all_models().filter(|m| m.families.contains(&parsed.family.as_str())) {
        let Some(score) = parsed.score(model) else { continue };
        if best.is_none_or(|(s, _)| score > s) {
            best = Some((score, model));
        }
    }
    best.map(|(_, model)| model)
}

/// Whether a name names a robot family at all (`ROB1_910SC_0.55_3` does, by its
/// number; a bare `ROB1` does not), whether or not we have a model of it.
pub fn names_a_family(name: &str) -> bool {
    ParsedName::of(name).is_some()
}

/// The robot family a name belongs to when it is one real cells use that we have no
/// kinematics for yet (`ROB1_910SC_0.55_3` → the IRB 910SC SCARA), so that the
/// refusal can say so; `None` for families we have and names we do not recognise.
pub fn unsupported_family(name: &str) -> Option<&'static str> {
    let family = ParsedName::of(name)?.family;
    Some(match family.as_str() {
        "14050" => "IRB 14050 single-arm YuMi (a 7-axis arm)",
        "910sc" | "910" | "920" | "920t" => "IRB 910SC/920 SCARA (4 axes)",
        "360" | "365" | "390" => "IRB 360/365/390 FlexPicker (a delta robot)",
        _ => return None,
    })
}

/// The YuMi arm a name of the IRB 14000 names: the left arm for a name with an `L` or
/// `LEFT` part (MOC.cfg's `ROB_L_14000_05_05`, a public backup's type; `ROB_L_14000_0.5_0.5`),
/// else the right arm (`ROB_R_…`, and a bare `IRB 14000`: ROB_R is the system's first
/// robot). The one variant (0.5 kg, 0.5 m) answers whatever numbers follow.
fn yumi_arm(name: &str) -> &'static RobotModel {
    let left =
        name.to_ascii_lowercase().split([' ', '_', '-', '/', ',', '\t']).any(|part| part == "l" || part == "left");
    &YUMI[usize::from(left)]
}

/// A robot name split into its family and the numbers after it.
struct ParsedName {
    family: String,
    /// Numbers written with a decimal point: reaches in metres.
    decimals: Vec<f64>,
    /// Whole numbers: handling capacities, or reaches in centimetres.
    integers: Vec<u32>,
}

impl ParsedName {
    fn of(name: &str) -> Option<ParsedName> {
        let lower = name.to_ascii_lowercase();
        let mut family = None;
        let mut decimals = Vec::new();
        let mut integers = Vec::new();
        // A name is short; a very long one is not a robot name, so the loop is bounded.
        for raw in lower.split([' ', '_', '-', '/', ',', '\t']).filter(|t| !t.is_empty()).take(16) {
            let token = raw.strip_prefix("irb").unwrap_or(raw);
            if token.is_empty() || is_rob_prefix(token) {
                continue;
            }
            if family.is_none() {
                if token.starts_with(|c: char| c.is_ascii_digit()) && token.is_ascii() {
                    family = Some(token.to_string());
                }
                continue;
            }
            if let Ok(n) = token.parse::<u32>() {
                integers.push(n);
            } else if let Ok(x) = token.parse::<f64>() {
                if x.is_finite() {
                    decimals.push(x);
                }
            }
            // Words such as `LeanID` or `TypeB` name options, not the geometry.
        }
        Some(ParsedName { family: family?, decimals, integers })
    }

    /// How well the numbers fit a model of the right family; `None` when one
    /// contradicts it.
    fn score(&self, model: &RobotModel) -> Option<usize> {
        let reach_matches = |x: f64| model.reaches.iter().any(|r| (r - x).abs() < 0.005);
        let reach_cm = |n: u32| model.reaches.iter().any(|r| (r * 100.0).round() as u32 == n);
        if !self.decimals.iter().all(|&x| reach_matches(x)) {
            return None;
        }
        let mut reach_named = !self.decimals.is_empty();
        let mut score = self.decimals.len();
        let mut unmatched = 0;
        for &n in &self.integers {
            if model.payloads.contains(&n) {
                score += 1;
            } else if reach_cm(n) {
                reach_named = true;
                score += 1;
            } else {
                unmatched += 1;
            }
        }
        // uncertain: a capacity we do not list (LeanID 220 kg on the 6700-2.65 arm) is
        // taken to be a variant of the same arm when the reach names the geometry.
        if unmatched > 0 && !reach_named {
            return None;
        }
        Some(score)
    }
}

/// `rob1`, `rob_1` split to `rob`: the robot-number prefix of a MOC.cfg robot type.
fn is_rob_prefix(token: &str) -> bool {
    token.strip_prefix("rob").is_some_and(|rest| rest.chars().all(|c| c.is_ascii_digit()))
}

const fn opw(a1: f64, a2: f64, c1: f64, c2: f64, c3: f64, c4: f64) -> OpwParams {
    // The table in motion.md is in metres; we keep millimetres.
    OpwParams {
        a1: a1 * 1000.0,
        a2: a2 * 1000.0,
        b: 0.0,
        c1: c1 * 1000.0,
        c2: c2 * 1000.0,
        c3: c3 * 1000.0,
        c4: c4 * 1000.0,
    }
}

const fn pallet(d1: f64, a1: f64, l2: f64, l3: f64, a4: f64, d5: f64) -> PalletParams {
    PalletParams { d1, a1, l2, l3, a4, d5 }
}

const NO_OPW: OpwParams = OpwParams { a1: 0.0, a2: 0.0, b: 0.0, c1: 0.0, c2: 0.0, c3: 0.0, c4: 0.0 };
const IRB660: PalletParams = pallet(800.0, 300.0, 1280.0, 1350.0, 260.0, 247.0);

/// A palletizer's axis ranges: axis 1 symmetric, axes 2 and 3 as given, axis 6 ±300°;
/// axes 4 and 5 do not exist (held at 0).
const fn pallet_limits(ax1: f64, ax2: (f64, f64), ax3: (f64, f64)) -> [(f64, f64); 6] {
    [sym(ax1), ax2, ax3, (0.0, 0.0), (0.0, 0.0), sym(300.0)]
}

/// A palletizer's axis speeds; the absent axes 4 and 5 get axis 6's so that no
/// computation divides by zero (they never move).
const fn pallet_speeds(ax1: f64, ax2: f64, ax3: f64, ax6: f64) -> [f64; 6] {
    [ax1, ax2, ax3, ax6, ax6, ax6]
}

const fn sym(x: f64) -> (f64, f64) {
    (-x, x)
}

const IRB120_LIMITS: [(f64, f64); 6] = [sym(165.0), sym(110.0), (-110.0, 70.0), sym(160.0), sym(120.0), sym(400.0)];
const IRB4600_LIMITS: [(f64, f64); 6] =
    [sym(180.0), (-90.0, 150.0), (-180.0, 75.0), sym(400.0), (-125.0, 120.0), sym(400.0)];
const IRB1200_GEOMETRY_5_90: OpwParams = opw(0.0, -0.042, 0.3991, 0.448, 0.451, 0.082);
const IRB1600_LIMITS_12: [(f64, f64); 6] =
    [sym(180.0), (-63.0, 110.0), (-235.0, 55.0), sym(200.0), sym(115.0), sym(400.0)];

// Max TCP speeds: IRB 120 6.2 m/s and IRB 1200-5/0.9 8.4 m/s are the MOTION_PLANNER
// `-linear_max_speed` of public robot backups (MOC.cfg of joseballester/abb-rapidserver,
// robot type ROB1_120_0.58_3, and of panin-anan/abb_SAMXL_Grinding_RAPID,
// ROB1_1200_0.9_5_TypeB). uncertain: the IRB 120T is taken to share the IRB 120's
// figure, and the IRB 140's 2.5 m/s is its product specification as we remember it.
#[rustfmt::skip]
static MODELS: &[RobotModel] = &[
    RobotModel { name: "IRB 120-3/0.58", families: &["120"], payloads: &[3], reaches: &[0.58],
        opw: opw(0.0, -0.070, 0.290, 0.270, 0.302, 0.072), limits: IRB120_LIMITS,
        max_speeds: [250.0, 250.0, 250.0, 320.0, 320.0, 420.0],
        max_tcp_speed: Some(6200.0), pallet: None, yumi: None },
    RobotModel { name: "IRB 120T-3/0.58", families: &["120t"], payloads: &[3], reaches: &[0.58],
        opw: opw(0.0, -0.070, 0.290, 0.270, 0.302, 0.072), limits: IRB120_LIMITS,
        max_speeds: [250.0, 250.0, 250.0, 420.0, 590.0, 600.0],
        max_tcp_speed: Some(6200.0), pallet: None, yumi: None },
    // uncertain: motion.md gives the limits of the 140T only; the 140 is taken to share them.
    RobotModel { name: "IRB 140-6/0.81", families: &["140", "140t"], payloads: &[6], reaches: &[0.81],
        opw: opw(0.070, 0.0, 0.352, 0.360, 0.380, 0.065),
        limits: [sym(180.0), (-90.0, 110.0), (-230.0, 50.0), sym(200.0), sym(115.0), sym(400.0)],
        max_speeds: [250.0, 250.0, 260.0, 360.0, 360.0, 450.0],
        max_tcp_speed: Some(2500.0), pallet: None, yumi: None },
    RobotModel { name: "IRB 1200-5/0.9", families: &["1200"], payloads: &[5], reaches: &[0.9],
        opw: IRB1200_GEOMETRY_5_90,
        limits: [sym(170.0), (-100.0, 130.0), (-200.0, 70.0), sym(270.0), sym(130.0), sym(360.0)],
        max_speeds: [288.0, 240.0, 300.0, 400.0, 405.0, 600.0],
        max_tcp_speed: Some(8400.0), pallet: None, yumi: None },
    RobotModel { name: "IRB 1200-7/0.7", families: &["1200"], payloads: &[7], reaches: &[0.7],
        opw: opw(0.0, -0.042, 0.3991, 0.350, 0.351, 0.082),
        limits: [sym(170.0), (-100.0, 135.0), (-200.0, 70.0), sym(270.0), sym(130.0), sym(360.0)],
        max_speeds: [288.0, 240.0, 300.0, 400.0, 405.0, 600.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 1600-6/1.2", families: &["1600"], payloads: &[6, 10], reaches: &[1.2],
        opw: opw(0.150, 0.0, 0.4865, 0.475, 0.600, 0.065), limits: IRB1600_LIMITS_12,
        max_speeds: [150.0, 160.0, 170.0, 320.0, 400.0, 450.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 1600-10/1.45", families: &["1600"], payloads: &[8, 10], reaches: &[1.45],
        opw: opw(0.150, 0.0, 0.4865, 0.700, 0.600, 0.065),
        limits: [sym(180.0), (-90.0, 120.0), (-245.0, 65.0), sym(200.0), sym(115.0), sym(400.0)],
        max_speeds: [180.0, 180.0, 200.0, 400.0, 400.0, 460.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    // uncertain: the reaches that name the 2400 (1.55 m for /10, 1.5 m for /16) are from memory.
    RobotModel { name: "IRB 2400-10/1.55", families: &["2400"], payloads: &[10, 16], reaches: &[1.55, 1.5],
        opw: opw(0.100, -0.135, 0.615, 0.705, 0.755, 0.085),
        limits: [sym(180.0), (-100.0, 110.0), (-60.0, 65.0), sym(200.0), sym(120.0), sym(400.0)],
        max_speeds: [150.0, 150.0, 150.0, 360.0, 360.0, 450.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 2600-12/1.65", families: &["2600"], payloads: &[12], reaches: &[1.65],
        opw: opw(0.150, -0.115, 0.445, 0.700, 0.795, 0.085),
        limits: [sym(180.0), (-155.0, 95.0), (-155.0, 75.0), sym(400.0), sym(120.0), sym(400.0)],
        max_speeds: [175.0, 175.0, 175.0, 360.0, 360.0, 500.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 4600-60/2.05", families: &["4600"], payloads: &[60], reaches: &[2.05],
        opw: opw(0.175, -0.175, 0.495, 0.900, 0.960, 0.135), limits: IRB4600_LIMITS,
        max_speeds: [175.0, 175.0, 175.0, 250.0, 250.0, 360.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 4600-40/2.55", families: &["4600"], payloads: &[40], reaches: &[2.55],
        opw: opw(0.175, -0.175, 0.495, 1.095, 1.270, 0.135), limits: IRB4600_LIMITS,
        max_speeds: [175.0, 175.0, 175.0, 250.0, 250.0, 360.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 4600-20/2.50", families: &["4600"], payloads: &[20], reaches: &[2.50],
        opw: opw(0.175, -0.175, 0.495, 1.095, 1.2305, 0.085), limits: IRB4600_LIMITS,
        max_speeds: [175.0, 175.0, 175.0, 360.0, 360.0, 500.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 6640-185/2.8", families: &["6640"], payloads: &[185], reaches: &[2.8],
        opw: opw(0.320, -0.200, 0.780, 1.075, 1.392, 0.200),
        limits: [sym(170.0), (-65.0, 85.0), (-180.0, 70.0), sym(300.0), sym(120.0), sym(360.0)],
        max_speeds: [100.0, 90.0, 90.0, 170.0, 140.0, 190.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 6700-200/2.60", families: &["6700"], payloads: &[200], reaches: &[2.60],
        opw: opw(0.320, -0.200, 0.780, 1.125, 1.1425, 0.200),
        limits: [sym(170.0), (-65.0, 85.0), (-180.0, 70.0), sym(300.0), sym(130.0), sym(360.0)],
        max_speeds: [110.0, 110.0, 110.0, 190.0, 150.0, 210.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 6700-235/2.65", families: &["6700"], payloads: &[235], reaches: &[2.65],
        opw: opw(0.320, -0.200, 0.780, 1.135, 1.1825, 0.200),
        limits: [sym(170.0), (-65.0, 85.0), (-180.0, 70.0), sym(300.0), sym(130.0), sym(360.0)],
        max_speeds: [100.0, 90.0, 90.0, 170.0, 120.0, 190.0],
        max_tcp_speed: None, pallet: None, yumi: None },
    RobotModel { name: "IRB 7600-150/3.5", families: &["7600"], payloads: &[150], reaches: &[3.5],
        opw: opw(0.410, -0.165, 0.780, 1.075, 2.012, 0.250),
        limits: [sym(180.0), (-60.0, 85.0), (-180.0, 60.0), sym(300.0), sym(100.0), sym(360.0)],
        max_speeds: [100.0, 60.0, 60.0, 100.0, 100.0, 190.0],
        max_tcp_speed: None, pallet: None, yumi: None },
];

#[rustfmt::skip]
static PALLETIZERS: &[RobotModel] = &[
    // The 4-axis palletizers. Link lengths: the modified Denavit-Hartenberg tables of
    // SaltworkerMLU/robotkinematicscatalogue (robotKinematics/inverseKinematics/__4DOF/
    // __palletizing/ABB_IRB260.py, ABB_IRB460.py, ABB_IRB660_180.py, ABB_IRB660_250.py,
    // ABB_IRB760.py, checked there against RoboDK's ABB models), as (axis-2 height,
    // axis-2 offset, lower arm, upper arm, flange offset, flange drop); axis ranges 1, 2,
    // 3 and 6 from the same files. The zero-axis flange is at x = a1 + l3 + a4,
    // z = d1 + l2 − d5 (tests/kinematics.rs checks the table).
    // uncertain: the axis speeds are the product specifications' as we remember them
    // (IRB 460: 145/110/120/400 °/s; IRB 660-180: 130/130/130/300, -250: 95/95/95/240;
    // IRB 760: 85/85/85/190 is a guess from the 660-250's class; IRB 260: 150 on the arm
    // axes, 400 on axis 6); axes 4 and 5 do not exist and are held at 0.
    RobotModel { name: "IRB 260-30/1.53", families: &["260"], payloads: &[30], reaches: &[1.53, 1.5],
        opw: NO_OPW, pallet: Some(pallet(615.0, 100.0, 705.0, 650.0, 120.0, 181.0)),
        limits: pallet_limits(180.0, (-28.0, 85.0), (-17.0, 119.0)),
        max_speeds: pallet_speeds(150.0, 150.0, 150.0, 400.0),
        max_tcp_speed: None, yumi: None },
    RobotModel { name: "IRB 460-110/2.4", families: &["460"], payloads: &[110], reaches: &[2.4],
        opw: NO_OPW, pallet: Some(pallet(745.0, 260.0, 945.0, 1025.0, 225.0, 251.5)),
        limits: pallet_limits(165.0, (-40.0, 85.0), (-20.0, 120.0)),
        max_speeds: pallet_speeds(145.0, 110.0, 120.0, 400.0),
        max_tcp_speed: None, yumi: None },
    RobotModel { name: "IRB 660-180/3.15", families: &["660"], payloads: &[180], reaches: &[3.15],
        opw: NO_OPW, pallet: Some(IRB660),
        limits: pallet_limits(180.0, (-42.0, 82.0), (-20.0, 120.0)),
        max_speeds: pallet_speeds(130.0, 130.0, 130.0, 300.0),
        max_tcp_speed: None, yumi: None },
    RobotModel { name: "IRB 660-250/3.15", families: &["660"], payloads: &[250], reaches: &[3.15],
        opw: NO_OPW, pallet: Some(IRB660),
        limits: pallet_limits(180.0, (-42.0, 82.0), (-20.0, 120.0)),
        max_speeds: pallet_speeds(95.0, 95.0, 95.0, 240.0),
        max_tcp_speed: None, yumi: None },
    RobotModel { name: "IRB 760-450/3.18", families: &["760"], payloads: &[450], reaches: &[3.18],
        opw: NO_OPW, pallet: Some(pallet(814.5, 300.0, 1280.0, 1350.0, 290.0, 269.0)),
        limits: pallet_limits(180.0, (-42.0, 82.0), (-20.0, 120.0)),
        max_speeds: pallet_speeds(85.0, 85.0, 85.0, 190.0),
        max_tcp_speed: None, yumi: None },
];

/// The IRB 14000 YuMi's arms: axes 1..6 of `kinematics::yumi::LIMITS` and `SPEEDS`
/// (axis 7 rides in eax_a, see `kinematics/yumi.rs`); their ranges agree with a public
/// YuMi backup's MOC.cfg `ARM` bounds (±2.94088 rad = ±168.5° on axis 1, −2.50455 ..
/// 0.759218 rad = −143.5° .. 43.5° on axis 2, …), and its `MOTION_PLANNER
/// -linear_max_speed 1.5` gives the TCP speed, 1.5 m/s.
static YUMI: &[RobotModel] =
    &[yumi_model("IRB 14000-0.5/0.5 ROB_R", Side::Right), yumi_model("IRB 14000-0.5/0.5 ROB_L", Side::Left)];

const fn yumi_model(name: &'static str, side: Side) -> RobotModel {
    let l = yumi::LIMITS;
    let v = yumi::SPEEDS;
    RobotModel {
        name,
        families: &["14000"],
        payloads: &[],
        reaches: &[0.5],
        opw: NO_OPW,
        pallet: None,
        limits: [l[0], l[1], l[2], l[3], l[4], l[5]],
        max_speeds: [v[0], v[1], v[2], v[3], v[4], v[5]],
        max_tcp_speed: Some(1500.0),
        yumi: Some(side),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn name_of(s: &str) -> Option<&'static str> {
        find_model(s).map(|m| m.name)
    }

    #[test]
    fn names_users_write() {
        assert_eq!(name_of("IRB120"), Some("IRB 120-3/0.58"));
        assert_eq!(name_of("IRB 120-3/0.58"), Some("IRB 120-3/0.58"));
        assert_eq!(name_of("irb120_3_58"), Some("IRB 120-3/0.58"));
        assert_eq!(name_of("IRB 120T"), Some("IRB 120T-3/0.58"));
        assert_eq!(name_of("irb4600_40_255"), Some("IRB 4600-40/2.55"));
        assert_eq!(name_of("IRB 4600-20/2.50"), Some("IRB 4600-20/2.50"));
        assert_eq!(name_of("IRB 4600"), Some("IRB 4600-60/2.05"));
        assert_eq!(name_of("irb1600-8/1.45"), Some("IRB 1600-10/1.45"));
        assert_eq!(name_of("IRB 140T"), Some("IRB 140-6/0.81"));
        assert_eq!(name_of("irb6640_185_280"), Some("IRB 6640-185/2.8"));
    }

    #[test]
    fn moc_robot_types() {
        assert_eq!(name_of("ROB1_120_0.58"), Some("IRB 120-3/0.58"));
        assert_eq!(name_of("ROB1_1200_0.9_5_TypeB"), Some("IRB 1200-5/0.9"));
        assert_eq!(name_of("ROB1_1200_0.7_7"), Some("IRB 1200-7/0.7"));
        assert_eq!(name_of("ROB1_6700_LeanID_2.65_220"), Some("IRB 6700-235/2.65"));
        assert_eq!(name_of("rob2_2600_1.65_12"), Some("IRB 2600-12/1.65"));
    }

    #[test]
    fn names_that_fit_nothing() {
        assert_eq!(name_of(""), None);
        assert_eq!(name_of("IRB"), None);
        assert_eq!(name_of("IRB 999"), None);
        assert_eq!(name_of("IRB 4600-999/9.9"), None);
        assert_eq!(name_of("IRB 120-3/2.5"), None);
        assert_eq!(name_of("KUKA KR6"), None);
    }

    #[test]
    fn families_we_lack_are_named() {
        assert_eq!(unsupported_family("ROB_L_14000_0.5_0.5"), None);
        assert!(unsupported_family("ROB1_14050_0.5_0.5").is_some_and(|f| f.contains("YuMi")));
        assert!(unsupported_family("ROB1_910SC_0.55_3").is_some_and(|f| f.contains("SCARA")));
        assert_eq!(unsupported_family("ROB1_120_0.58_3"), None);
        assert_eq!(unsupported_family("KUKA KR6"), None);
        assert!(names_a_family("ROB1_910SC_0.55_3") && names_a_family("IRB 999"));
        assert!(!names_a_family("ROB1") && !names_a_family("ROB_L"));
    }

    #[test]
    fn yumi_types_name_their_arm() {
        // A public YuMi backup's MOC.cfg writes `ROB_R_14000_05_05` and `ROB_L_14000_05_05`.
        assert_eq!(find_model("ROB_R_14000_05_05").and_then(|m| m.yumi), Some(Side::Right));
        assert_eq!(find_model("ROB_L_14000_05_05").and_then(|m| m.yumi), Some(Side::Left));
        assert_eq!(find_model("ROB_L_14000_0.5_0.5").and_then(|m| m.yumi), Some(Side::Left));
        assert_eq!(find_model("IRB 14000").and_then(|m| m.yumi), Some(Side::Right));
        let left = find_model("ROB_L_14000_0.5_0.5").unwrap();
        assert_eq!(left.limits[1], (-143.5, 43.5));
        assert_eq!(left.calibration(), [0.0, -130.0, 30.0, 0.0, 40.0, 0.0]);
        assert_eq!(default_model().calibration(), [0.0; 6]);
    }

    #[test]
    fn calibration_position_matches_the_table() {
        // motion.md §2.2: tool0 at zero is x = a1 + c3 + c4, z = c1 + c2 − a2.
        let m = find_model("IRB 140").unwrap();
        let p = m.opw;
        assert!((p.a1 + p.c3 + p.c4 - 515.0).abs() < 1e-9);
        assert!((p.c1 + p.c2 - p.a2 - 712.0).abs() < 1e-9);
        assert_eq!(default_model().name, "IRB 120-3/0.58");
    }

    #[test]
    fn tcp_speed_from_the_data_sheet_or_the_geometry() {
        assert_eq!(default_model().tcp_speed(), 6200.0);
        // IRB 2400-10/1.55 by hand: lower arm √(705² + 135²) = 717.81 mm, wrist
        // 755 + 85 = 840 mm; radii 100 + 717.81 + 840 = 1657.81, 1557.81 and 840 mm,
        // all at 150°/s = 2.61799 rad/s: (1657.81 + 1557.81 + 840) × 2.61799 = 10617.6.
        let v = find_model("IRB 2400").unwrap().tcp_speed();
        assert!((v - 10617.6).abs() < 0.5, "{v}");
    }
}
