//! Motion data in plain Rust: speeddata, zonedata and the motion settings that
//! AccSet, VelSet and the speed override change, with RAPID's predefined values.

/// RAPID `speeddata`: TCP speed (mm/s), reorientation speed (°/s), linear and
/// rotating external-axis speeds (mm/s, °/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedData {
    pub v_tcp: f64,
    pub v_ori: f64,
    pub v_leax: f64,
    pub v_reax: f64,
}

/// RAPID `zonedata`: stop point or the sizes of the fly-by zones (mm and °).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneData {
    pub finep: bool,
    pub pzone_tcp: f64,
    pub pzone_ori: f64,
    pub pzone_eax: f64,
    pub zone_ori: f64,
    pub zone_leax: f64,
    pub zone_reax: f64,
}

/// The motion settings a move is planned with: AccSet, VelSet and the operator's
/// speed override. `Default` is the state after program reset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionSettings {
    /// AccSet Acc: acceleration and deceleration, % of the nominal values.
    pub acc: f64,
    /// AccSet Ramp: rate of change of acceleration, % of nominal. Stored so the
    /// VM can read it back; the trapezoid profile has no jerk phase to scale.
    pub ramp: f64,
    /// VelSet Override: programmed speeds scaled by this %.
    pub vel_override: f64,
    /// VelSet Max: cap on the TCP speed, mm/s.
    pub vel_max: f64,
    /// The operator's speed override (FlexPendant), %.
    pub speed_override: f64,
    /// How circles reorient the tool (CirPathMode).
    pub circle_ori: CircleOri,
    /// `\T` of the move being pushed: it takes this many seconds (the programmed
    /// speeds give way; axis limits still hold). `None`: the speeddata rules.
    pub move_time: Option<f64>,
    /// `\Inpos` of the move being pushed: the time it stands at its stop point
    /// before it is done (in place of the `fine` settle time), s.
    pub stop_time: Option<f64>,
    /// PathAccLim and WorldAccLim together: the most the TCP may accelerate and brake
    /// along a linear or circular path, mm/s² (`None`: no limit).
    pub tcp_acc_max: Option<f64>,
    pub tcp_dec_max: Option<f64>,
    /// SingArea\Wrist: linear and circular moves interpolate the wrist axes in joint
    /// space while the TCP keeps its path (`wrist.rs`); \Off (false) keeps the
    /// programmed orientation.
    pub sing_wrist: bool,
    /// How far a track carries the robot's base over the move being pushed (mm, in
    /// the base frame; zero without one): a circle's targets are relative to the base
    /// where the move ends, and the circle is kept in the world.
    pub base_travel: [f64; 3],
}

/// How a circular move reorients the tool (CirPathMode; the wrist modes are not
/// planned: the VM refuses them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CircleOri {
    /// `\PathFrame` (the default): relative to the path's tangent.
    #[default]
    PathFrame,
    /// `\ObjectFrame`: in the work object, from the start's orientation to the end's.
    ObjectFrame,
    /// `\CirPointOri`: through the circle point's orientation.
    CirPointOri,
}

impl Default for MotionSettings {
    fn default() -> Self {
        // uncertain: VelSet's default Max; older manuals say 5000 mm/s, newer ones
        // the robot's maximum TCP speed (motion.md §3.1). 5000 is the documented one.
        MotionSettings {
            acc: 100.0,
            ramp: 100.0,
            vel_override: 100.0,
            vel_max: 5000.0,
            speed_override: 100.0,
            circle_ori: CircleOri::PathFrame,
            move_time: None,
            stop_time: None,
            tcp_acc_max: None,
            tcp_dec_max: None,
            sing_wrist: false,
            base_travel: [0.0; 3],
        }
    }
}

impl MotionSettings {
    /// The factor applied to nominal accelerations. AccSet's Acc is clamped to
    /// 20..=100 %, the range the manual gives (uncertain: whether values below 20
    /// are raised or refused).
    pub fn acc_factor(&self) -> f64 {
        let acc = if self.acc.is_finite() { self.acc } else { 100.0 };
        acc.clamp(20.0, 100.0) / 100.0
    }

    /// The factor VelSet's override and the speed override scale speeds by (0 ..= 1).
    pub fn speed_factor(&self) -> f64 {
        let percent = |p: f64| if p.is_finite() { p.clamp(0.0, 100.0) / 100.0 } else { 1.0 };
        percent(self.vel_override) * percent(self.speed_override)
    }

    /// The programmed speeds after VelSet and the speed override: every speed is
    /// scaled, and the TCP speed is capped at VelSet's Max.
    pub fn effective_speed(&self, speed: &SpeedData) -> SpeedData {
        let k = self.speed_factor();
        let clean = |v: f64| if v.is_finite() { v.max(0.0) } else { 0.0 };
        let vel_max = if self.vel_max.is_finite() && self.vel_max > 0.0 { self.vel_max } else { f64::INFINITY };
        SpeedData {
            v_tcp: (clean(speed.v_tcp) * k).min(vel_max),
            v_ori: clean(speed.v_ori) * k,
            v_leax: clean(speed.v_leax) * k,
            v_reax: clean(speed.v_reax) * k,
        }
    }
}

/// The numbered speeds v5 … v7000; each is `[N, 500, 5000, 1000]`.
const SPEED_STEPS: [u32; 25] = [
    5, 10, 20, 30, 40, 50, 60, 80, 100, 150, 200, 300, 400, 500, 600, 800, 1000, 1500, 2000, 2500, 3000, 4000, 5000,
    6000, 7000,
];

impl SpeedData {
    /// `vmax` as older systems define it. uncertain: RW 6 sets v_tcp to the robot
    /// type's maximum TCP speed (what MaxRobSpeed returns); the VM should replace
    /// v_tcp with that value when the robot model gives it.
    pub const VMAX: SpeedData = SpeedData { v_tcp: 5000.0, v_ori: 500.0, v_leax: 5000.0, v_reax: 1000.0 };

    /// A predefined speeddata by its RAPID name (case-insensitive, as RAPID names
    /// are): `v5` … `v7000` and `vmax`.
    pub fn predefined(name: &str) -> Option<SpeedData> {
        let lower = name.to_ascii_lowercase();
        if lower == "vmax" {
            return Some(Self::VMAX);
        }
        let n: u32 = lower.strip_prefix('v')?.parse().ok()?;
        if !SPEED_STEPS.contains(&n) || lower != format!("v{n}") {
            return None;
        }
        Some(SpeedData { v_tcp: f64::from(n), v_ori: 500.0, v_leax: 5000.0, v_reax: 1000.0 })
    }
}

/// Predefined zones, one row each: name, pzone_tcp, pzone_ori (= pzone_eax =
/// zone_leax), zone_ori (= zone_reax). motion.md §3.2.
#[rustfmt::skip]
const ZONES: [(&str, f64, f64, f64); 15] = [
    ("z0",   0.3,   0.3, 0.03),
    ("z1",   1.0,   1.0, 0.1),
    ("z5",   5.0,   8.0, 0.8),
    ("z10",  10.0,  15.0, 1.5),
    ("z15",  15.0,  23.0, 2.3),
    ("z20",  20.0,  30.0, 3.0),
    ("z30",  30.0,  45.0, 4.5),
    ("z40",  40.0,  60.0, 6.0),
    ("z50",  50.0,  75.0, 7.5),
    ("z60",  60.0,  90.0, 9.0),
    ("z80",  80.0,  120.0, 12.0),
    ("z100", 100.0, 150.0, 15.0),
    ("z150", 150.0, 225.0, 23.0),
    ("z200", 200.0, 300.0, 30.0),
    ("fine", 0.0,   0.0, 0.0),
];

impl ZoneData {
    /// `fine`: a stop point.
    pub const FINE: ZoneData = ZoneData {
        finep: true,
        pzone_tcp: 0.0,
        pzone_ori: 0.0,
        pzone_eax: 0.0,
        zone_ori: 0.0,
        zone_leax: 0.0,
        zone_reax: 0.0,
    };

    /// A predefined zonedata by its RAPID name (case-insensitive): `fine`, `z0`
    /// … `z200`.
    pub fn predefined(name: &str) -> Option<ZoneData> {
        let lower = name.to_ascii_lowercase();
        let &(_, tcp, ori, deg) = ZONES.iter().find(|row| row.0 == lower)?;
        if lower == "fine" {
            return Some(Self::FINE);
        }
        Some(ZoneData {
            finep: false,
            pzone_tcp: tcp,
            pzone_ori: ori,
            pzone_eax: ori,
            zone_ori: deg,
            zone_leax: ori,
            zone_reax: deg,
        })
    }

    /// A fly-by zone whose TCP zone is `mm`, the other fields following the
    /// predefined pattern (1.5 × mm, 0.15 × mm in degrees). For tests and `\Z`.
    pub fn fly_by(mm: f64) -> ZoneData {
        ZoneData {
            finep: false,
            pzone_tcp: mm,
            pzone_ori: 1.5 * mm,
            pzone_eax: 1.5 * mm,
            zone_ori: 0.15 * mm,
            zone_leax: 1.5 * mm,
            zone_reax: 0.15 * mm,
        }
    }

    /// Whether the move ends in a stop point: `finep`, or a zone of no size.
    pub fn is_stop(&self) -> bool {
        self.finep || self.pzone_tcp.is_nan() || self.pzone_tcp <= 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn predefined_speeds() {
        assert_eq!(SpeedData::predefined("v1000").map(|s| s.v_tcp), Some(1000.0));
        assert_eq!(SpeedData::predefined("V5").map(|s| s.v_ori), Some(500.0));
        assert_eq!(SpeedData::predefined("vmax"), Some(SpeedData::VMAX));
        assert_eq!(SpeedData::predefined("v7"), None);
        assert_eq!(SpeedData::predefined("v0100"), None);
        assert_eq!(SpeedData::predefined("v"), None);
    }

    #[test]
    fn predefined_zones() {
        let z10 = ZoneData::predefined("z10").unwrap();
        assert_eq!((z10.pzone_tcp, z10.pzone_ori, z10.zone_ori, z10.zone_leax), (10.0, 15.0, 1.5, 15.0));
        assert!(ZoneData::predefined("FINE").unwrap().is_stop());
        assert_eq!(ZoneData::predefined("z0").unwrap().zone_reax, 0.03);
        assert_eq!(ZoneData::predefined("z150").unwrap().zone_ori, 23.0);
        assert_eq!(ZoneData::predefined("z7"), None);
    }

    #[test]
    fn velset_scales_and_caps() {
        let s = MotionSettings { vel_override: 50.0, vel_max: 300.0, ..MotionSettings::default() };
        let v = s.effective_speed(&SpeedData::predefined("v1000").unwrap());
        assert_eq!((v.v_tcp, v.v_ori), (300.0, 250.0));
        let nan = MotionSettings { acc: f64::NAN, ..MotionSettings::default() };
        assert_eq!(nan.acc_factor(), 1.0);
        assert_eq!(MotionSettings { acc: 5.0, ..nan }.acc_factor(), 0.2);
    }
}
