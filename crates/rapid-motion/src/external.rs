//! External axes (§2.1 extjoint, §1.8 MoveExtJ): the logical axes 7–12 a robot task
//! moves besides the arm's six — a track, a positioner's turntable — whose values a
//! robtarget's or jointtarget's `extax` (`eax_a` … `eax_f`) program.
//!
//! Each axis moves with the arm: the planner paces a move so the arm and every
//! external axis start and stop together (see `plan::ExternalMove`). A unit with a
//! frame carries work objects ([`UnitChain`]: §2.1.2 协调附加轴, a user frame that
//! follows the unit's axes); the VM makes the robot follow them and carries the
//! robot's base on a track.

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
    /// Where the axis sits on the frame the axis before it carries (the unit's frame
    /// for the first): a rotating axis turns about this frame's z axis, a linear one
    /// moves along its x axis. Only units that carry work objects use it.
    pub mount: crate::Pose,
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

/// The most axes a unit's chain has (`extjoint` has six values).
const MAX_LINKS: usize = 6;

/// One axis of a [`UnitChain`]: its `extjoint` index and how it moves its mount.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Link {
    index: usize,
    linear: bool,
    mount: crate::Pose,
}

/// A unit's axes as a kinematic chain (a positioner's tilt axis carrying its turntable,
/// §2.1.2's three-axis unit): the frame work objects ride is the unit's frame, then
/// each axis in the unit's order, mounted on the one before and moved by its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitChain {
    frame: crate::Pose,
    links: [Option<Link>; MAX_LINKS],
}

impl UnitChain {
    /// The frame work objects ride, in the world, with the axes at `eax` (values of
    /// axes that are unused or not finite count as 0).
    pub fn frame_at(&self, eax: &Eax) -> crate::Pose {
        let mut frame = self.frame;
        for link in self.links.iter().flatten() {
            let value = eax[link.index];
            let value = if is_unused(value) { 0.0 } else { value };
            frame = frame * link.mount * axis_motion(link.linear, value);
        }
        frame
    }

    /// The motion (in the world) that carries an object riding the chain from the axes
    /// at `from` to the axes at `to`.
    pub fn carry(&self, from: &Eax, to: &Eax) -> crate::Pose {
        self.frame_at(to) * self.frame_at(from).inverse()
    }
}

/// How an axis moves what it carries by `value`: a linear axis along x (mm), a
/// rotating one about z (degrees).
fn axis_motion(linear: bool, value: f64) -> crate::Pose {
    use nalgebra::{Translation3, UnitQuaternion, Vector3};
    if linear {
        crate::Pose::from_parts(Translation3::new(value, 0.0, 0.0), UnitQuaternion::identity())
    } else {
        crate::Pose::from_parts(
            Translation3::identity(),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), value.to_radians()),
        )
    }
}

impl ExternalUnit {
    /// The chain that carries this unit's work objects, `None` when the unit has no
    /// frame (it carries none).
    pub fn chain(&self) -> Option<UnitChain> {
        let frame = self.frame?;
        let mut links = [None; MAX_LINKS];
        for (slot, axis) in links.iter_mut().zip(&self.axes) {
            *slot = Some(Link { index: axis.index(), linear: axis.linear, mount: axis.mount });
        }
        Some(UnitChain { frame, links })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion, Vector3};

    fn axis(logical: u8, linear: bool, mount: crate::Pose) -> ExternalAxis {
        ExternalAxis { logical, linear, min: -360.0, max: 360.0, max_speed: 90.0, acc: 600.0, start: 0.0, mount }
    }

    fn unit(axes: Vec<ExternalAxis>, frame: crate::Pose) -> ExternalUnit {
        let name = "STN".to_string();
        ExternalUnit {
            name,
            axes,
            active_at_start: true,
            deactivation_forbidden: false,
            frame: Some(frame),
            carries_robot: false,
        }
    }

    #[test]
    fn a_tilting_positioner_carries_its_table() {
        // The tilt axis (eax_b) is mounted with its z axis along the world x axis at
        // (400, 0, 200); the table (eax_c) is mounted back upright on it. Tilt 30°, table
        // 90°: the object point (-100, 0, 200) turns to (0, -100, 200) on the table, then
        // about the world x axis by 30°: (0, -100·cos30 - 200·sin30, -100·sin30 +
        // 200·cos30) = (0, -186.603, 123.205) from (400, 0, 200).
        let z_to_x = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 90f64.to_radians());
        let tilt = axis(8, false, crate::Pose::from_parts(Translation3::identity(), z_to_x));
        let table = axis(9, false, crate::Pose::from_parts(Translation3::identity(), z_to_x.inverse()));
        let base = crate::Pose::from_parts(Translation3::new(400.0, 0.0, 200.0), UnitQuaternion::identity());
        let chain = unit(vec![tilt, table], base).chain().expect("a frame");
        let eax = [UNUSED_AXIS * 1.2, 30.0, 90.0, 9e9, 9e9, 9e9];
        let point = chain.frame_at(&eax) * nalgebra::Point3::new(-100.0, 0.0, 200.0);
        let expected = nalgebra::Point3::new(400.0, -186.60254, 323.20508);
        assert!((point - expected).norm() < 1e-4, "{point}");
        // Carrying from the axes at zero is the same motion.
        let zero = [0.0; 6];
        let carried = chain.carry(&zero, &eax) * (base * nalgebra::Point3::new(-100.0, 0.0, 200.0));
        assert!((carried - expected).norm() < 1e-4, "{carried}");
    }

    #[test]
    fn one_axis_turns_about_the_units_frame() {
        // A turntable at (400, 0, 200) turned +90° about z: (-100, 0, 200) on it goes to
        // (0, -100, 200) from its centre, (400, -100, 400) in the world.
        let base = crate::Pose::from_parts(Translation3::new(400.0, 0.0, 200.0), UnitQuaternion::identity());
        let chain = unit(vec![axis(8, false, crate::Pose::identity())], base).chain().expect("a frame");
        let point = chain.frame_at(&[0.0, 90.0, 0.0, 0.0, 0.0, 0.0]) * nalgebra::Point3::new(-100.0, 0.0, 200.0);
        assert!((point - nalgebra::Point3::new(400.0, -100.0, 400.0)).norm() < 1e-9, "{point}");
    }
}
