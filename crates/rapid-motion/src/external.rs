//! External axes (§2.1 extjoint, §1.8 MoveExtJ): the logical axes 7–12 a robot task
//! moves besides the arm's six — a track, a positioner's turntable — whose values a
//! robtarget's or jointtarget's `extax` (`eax_a` … `eax_f`) program.
//!
//! Each axis moves with the arm: the planner paces a move so the arm and every
//! external axis start and stop together (see `plan::ExternalMove`). Axes here are not
//! coordinated with the arm's frames: a track does not carry the robot's base and a
//! positioner does not carry a work object (those are refused by the VM).

/// External axis values in `eax_a` … `eax_f` order (mm for a linear axis, degrees for
/// a rotating one).
pub type Eax = [f64; 6];

/// An `extjoint` value at or above this marks an axis the target does not use (9E9).
// The mark is 9E9; values read back from single-precision data are a little off it.
pub const UNUSED_AXIS: f64 = 8.9e9;

/// Whether an `extjoint` value means "not used" (9E9, or anything not finite).
pub fn is_unused(value: f64) -> bool {
    !value.is_finite() || value.abs() >= UNUSED_AXIS
}

/// One external axis as the motion configuration describes it.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalAxis {
    /// The logical axis, 7 ..= 12 (`eax_a` is 7).
    pub logical: u8,
    /// A linear axis moves in mm (speed `v_leax`), a rotating one in degrees (`v_reax`).
    pub linear: bool,
    /// The working range, mm or degrees.
    pub min: f64,
    pub max: f64,
    /// The highest speed, mm/s or °/s.
    pub max_speed: f64,
    /// Acceleration at AccSet 100 %, mm/s² or °/s².
    pub acc: f64,
    /// Where the axis stands when the system starts.
    pub start: f64,
}

impl ExternalAxis {
    /// The index of the axis's value in an `extjoint` (0 for `eax_a`).
    pub fn index(&self) -> usize {
        usize::from(self.logical.saturating_sub(7)).min(5)
    }

    /// Whether `value` is inside the working range.
    pub fn in_range(&self, value: f64) -> bool {
        value >= self.min - 1e-6 && value <= self.max + 1e-6
    }
}

/// How far the external axes move in one move and how fast they may: axes with equal
/// `from` and `to` stand still.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalMove {
    pub from: Eax,
    pub to: Eax,
    /// Each axis's highest speed (0 for an axis that does not exist).
    pub max_speed: [f64; 6],
    /// Each axis's acceleration at AccSet 100 %.
    pub acc: [f64; 6],
    /// Which axes are linear (paced by `v_leax`; the others by `v_reax`).
    pub linear: [bool; 6],
}

impl ExternalMove {
    /// The axis values a fraction `f` (0 ..= 1) of the way.
    pub fn at(&self, f: f64) -> Eax {
        let f = if f.is_finite() { f.clamp(0.0, 1.0) } else { 1.0 };
        std::array::from_fn(|j| self.from[j] + f * (self.to[j] - self.from[j]))
    }

    /// The axes that move, with their distance (mm or °).
    pub(crate) fn moving(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        (0..6).map(|j| (j, (self.to[j] - self.from[j]).abs())).filter(|&(_, d)| d > 1e-9)
    }
}

/// A mechanical unit of external axes (MOC.cfg `MECHANICAL_UNIT`, or a manifest's
/// `[[unit]]`): a track, a positioner.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalUnit {
    pub name: String,
    pub axes: Vec<ExternalAxis>,
    /// Active when the system starts (`-activate_at_start_up`).
    pub active_at_start: bool,
    /// DeactUnit is refused (`-deactivation_forbidden`).
    pub deactivation_forbidden: bool,
    /// Where the unit carries work objects (a turntable turns them about this frame's
    /// z axis, a linear unit moves them along its x axis), in the world frame; `None`
    /// when it carries none.
    pub frame: Option<crate::Pose>,
    /// A track the robot stands on: its one linear axis moves the robot's base frame
    /// along `frame`'s x axis (the world x axis without a frame).
    pub carries_robot: bool,
}
