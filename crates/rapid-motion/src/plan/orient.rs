//! The reorientation zone of a fly-by point (pzone_ori): over `reach` mm of
//! path on either side of the point, the tool's orientation blends from one
//! move's interpolation into the next one's, the rotational analogue of the
//! parabolic position blend.

use nalgebra::UnitQuaternion;

use super::path::OriLerp;

/// Blends the orientation interpolations of two Cartesian moves around the
/// point between them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct OriZone {
    pub(crate) before: OriLerp,
    pub(crate) before_len: f64,
    pub(crate) after: OriLerp,
    pub(crate) after_len: f64,
    /// Half the zone's length along the path, mm; at most half of either move.
    pub(crate) reach: f64,
}

impl OriZone {
    /// The orientation at progress `x` (0 to 1) through the zone. As with the
    /// quadratic Bézier `A + (2x − x²)(P − A) + x²(B − P)`, the incoming
    /// move's last `reach` mm of rotation fades out while the outgoing move's
    /// first `reach` mm fades in; at both ends orientation and its rate match
    /// the unblended moves.
    pub(crate) fn at(&self, x: f64) -> UnitQuaternion<f64> {
        let x = if x.is_finite() { x.clamp(0.0, 1.0) } else { 0.0 };
        let f_before = (self.before_len - self.reach + (2.0 * x - x * x) * self.reach) / self.before_len;
        let f_after = x * x * self.reach / self.after_len;
        // The outgoing rotation so far, applied in the tool frame: it starts at
        // the programmed point's orientation, where the incoming one ends.
        let turned = self.after.from.inverse() * self.after.at(f_after);
        self.before.at(f_before) * turned
    }

    /// Progress through the zone at path parameter `s` of the incoming move,
    /// or `None` before the zone.
    pub(crate) fn progress_before(&self, s: f64) -> Option<f64> {
        let start = self.before_len - self.reach;
        (s > start).then(|| (s - start) / (2.0 * self.reach))
    }

    /// Progress through the zone at path parameter `s` of the outgoing move,
    /// or `None` after the zone.
    pub(crate) fn progress_after(&self, s: f64) -> Option<f64> {
        (s < self.reach).then(|| (s + self.reach) / (2.0 * self.reach))
    }

    /// Progress at curve parameter `u` of the TCP corner, whose position zone
    /// `zone` sits in the middle of this one.
    pub(crate) fn progress_corner(&self, u: f64, zone: f64) -> f64 {
        (self.reach - zone + 2.0 * zone * u) / (2.0 * self.reach)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn about_z(deg: f64) -> UnitQuaternion<f64> {
        UnitQuaternion::from_euler_angles(0.0, 0.0, deg.to_radians())
    }

    #[test]
    fn blend_meets_both_moves() {
        // In: 0° → 0° over 100 mm. Out: 0° → 90° over 100 mm. Reach 20 mm.
        let zone = OriZone {
            before: OriLerp::fixed(about_z(0.0), about_z(0.0)),
            before_len: 100.0,
            after: OriLerp::fixed(about_z(0.0), about_z(90.0)),
            after_len: 100.0,
            reach: 20.0,
        };
        assert!(zone.at(0.0).angle_to(&about_z(0.0)) < 1e-12);
        // x = 1: the outgoing move 20 mm in, 18° turned.
        assert!(zone.at(1.0).angle_to(&about_z(18.0)) < 1e-12);
        // Half way (at the point): x² · 20 = 5 mm of the outgoing turn, 4.5°,
        // already begun before the point is passed.
        assert!(zone.at(0.5).angle_to(&about_z(4.5)) < 1e-12);
        assert_eq!(zone.progress_before(70.0), None);
        assert_eq!(zone.progress_before(90.0), Some(0.25));
        assert_eq!(zone.progress_after(10.0), Some(0.75));
        assert_eq!(zone.progress_corner(0.5, 10.0), 0.5);
    }
}
