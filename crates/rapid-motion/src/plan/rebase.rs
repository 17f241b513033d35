//! Moving the waiting move rigidly (`Planner::rebase_pending`): the last move in a
//! moving work object (a conveyor's) was planned in the object's frame frozen when the
//! following began; when the next move is in a fixed work object, the waiting move is
//! carried to where the object will be when it ends, so the next move is planned from
//! there in the world and the two can share a corner (§2.2.3). The VM then carries the
//! rebased move's samples by the object's travel relative to that place.

use super::mount::Mount;
use super::path::{Geometry, OriLerp, OriMode};
use super::segment::{ik_along, Prepared};
use crate::{Joints, Kinematics, MotionError, Pose};

/// `prep`, starting at joints `start`, moved by `by` (in the base frame): its path and
/// joints, and its new start. A linear or circular path keeps its shape and length; a
/// joint move or a stationary tool's path (its TCP stands in the base frame) cannot be
/// moved so: `InvalidData`.
pub(crate) fn rebased<K: Kinematics + ?Sized>(
    kin: &K,
    prep: &Prepared,
    start: &Joints,
    by: &Pose,
) -> Result<(Prepared, Joints), MotionError> {
    if !matches!(prep.mount, Mount::Held(_)) {
        return Err(MotionError::InvalidData("a stationary tool's move cannot follow a moving work object"));
    }
    if prep.geom.wrist_interpolated() && by.rotation.angle() > 1e-12 {
        // SingArea\Wrist's wrist values belong to the orientation: a turn changes them.
        return Err(MotionError::InvalidData("a wrist-interpolated move cannot be turned"));
    }
    let start = kin.inverse_near(&(by * kin.forward(start)), start)?;
    let geom = match &prep.geom {
        // A joint move's path is no rigid shape: moved, its length and pace would change.
        Geometry::Joint { .. } => return Err(MotionError::InvalidData("a joint move cannot be moved rigidly")),
        Geometry::Line { p0, p1, ori } => {
            Geometry::Line { p0: (by * point(p0)).coords, p1: (by * point(p1)).coords, ori: turned(ori, by) }
        }
        Geometry::Arc { center, radius, e1, e2, sweep, ori, drift } => Geometry::Arc {
            center: (by * point(center)).coords,
            radius: *radius,
            e1: by.rotation * e1,
            e2: by.rotation * e2,
            sweep: *sweep,
            ori: turned(ori, by),
            drift: by.rotation * drift,
        },
    };
    let ext7 = prep.eax.as_deref().filter(|_| kin.redundant());
    let seeds = ik_along(kin, &geom, &prep.mount, &start, ext7)?;
    let end_joints = seeds.last().map_or(start, |(_, q)| *q);
    Ok((Prepared { geom, seeds, end_joints, ..prep.clone() }, start))
}

fn point(v: &nalgebra::Vector3<f64>) -> nalgebra::Point3<f64> {
    nalgebra::Point3::from(*v)
}

/// An orientation interpolation turned by `by`'s rotation.
fn turned(ori: &OriLerp, by: &Pose) -> OriLerp {
    let r = by.rotation;
    let mode = match ori.mode {
        OriMode::PathFrame { normal, sweep, turns } => {
            OriMode::PathFrame { normal: nalgebra::Unit::new_normalize(r * normal.into_inner()), sweep, turns }
        }
        OriMode::ViaPoint { via, at } => OriMode::ViaPoint { via: r * via, at },
        mode => mode,
    };
    OriLerp { from: r * ori.from, to: r * ori.to, mode }
}

#[cfg(test)]
mod tests {
    use crate::plan::{AccelLimits, MoveRequest, Planner, SpeedData, Target, ZoneData};
    use crate::{default_model, Kinematics, Pose};
    use nalgebra::{Translation3, UnitQuaternion, Vector3};

    #[test]
    fn a_rebased_move_ends_where_its_point_was_moved_to() {
        // A MoveL 100 mm along y with a z20 zone waits for its successor; moved 40 mm
        // along x, it ends 40 mm further along x, as long and as fast as before.
        let kin = default_model().kinematics();
        let start = [0.0, 10.0, 20.0, 0.0, 60.0, 0.0];
        let from = kin.forward(&start);
        let to = Pose::from_parts(
            Translation3::from(from.translation.vector + Vector3::new(0.0, 100.0, 0.0)),
            from.rotation,
        );
        let request = MoveRequest {
            target: Target::Linear(to),
            speed: SpeedData { v_tcp: 100.0, v_ori: 500.0, v_leax: 5000.0, v_reax: 1000.0 },
            zone: ZoneData::predefined("z20").unwrap(),
            tool: Pose::identity(),
            held_object: None,
            wobj: Pose::identity(),
        };
        let mut planner = Planner::new(start, AccelLimits::nominal(&kin.max_speeds()));
        assert!(planner.push(&kin, &request).unwrap().is_none());
        let stop_before = planner.pending_stop_time().unwrap();
        let by = Pose::from_parts(Translation3::new(40.0, 0.0, 0.0), UnitQuaternion::identity());
        planner.rebase_pending(&kin, &by).unwrap();
        assert!((planner.pending_stop_time().unwrap() - stop_before).abs() < 1e-9);
        let planned = planner.flush().unwrap();
        let end = kin.forward(&planned.end_joints).translation.vector;
        assert!((end - (to.translation.vector + Vector3::new(40.0, 0.0, 0.0))).norm() < 1e-6, "{end}");
        let first = planned.sample(&kin, planned.start).tcp.translation.vector;
        assert!((first - (from.translation.vector + Vector3::new(40.0, 0.0, 0.0))).norm() < 1e-6, "{first}");
    }
}
