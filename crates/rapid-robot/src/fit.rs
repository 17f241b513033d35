//! Frames from measured points (manual §1.7 "program displacement"): DefFrame (a
//! frame through three points), DefDFrame (the displacement between three original
//! and three moved points) and DefAccFrame (a least-squares rigid fit of 3..10 point
//! pairs, with its largest and mean error). Only the translations of the robtargets
//! are used. Degenerate input (points too close or on one line) raises ERR_FRAME.

use nalgebra::{Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};

use super::frame;
use rapid_vm::ext::{Ctx, Err, RapidError, Value};

type Res = Result<Option<Value>, RapidError>;

/// Points closer than this (mm), or a third point closer than this to the line
/// through the first two, do not define a frame.
// uncertain: the manual says only "not on the same line and not too close"; the
// limit is ours.
const MIN_SPREAD_MM: f64 = 0.01;

/// The translation of a robtarget argument.
fn point(ctx: &Ctx<'_>, arg: &Value) -> Result<Vector3<f64>, RapidError> {
    Ok(frame::trans_rot(ctx, &ctx.value(arg)?)?.0)
}

fn frame_error(ctx: &Ctx<'_>) -> RapidError {
    ctx.error(Err::Frame, "the points are too close or on one line: no frame can be calculated")
}

/// The frame with its x axis from p1 towards p2 and p3 in its xy plane on the side of
/// positive y; `origin` 1 puts the origin in p1, 2 in p2, 3 on the x axis where p3
/// lies on the y axis.
// uncertain: for \Origin:=2 the x axis still points from p1 towards p2.
fn three_point_frame(p: [Vector3<f64>; 3], origin: u8) -> Option<Isometry3<f64>> {
    let along = p[1] - p[0];
    if along.norm() < MIN_SPREAD_MM {
        return None;
    }
    let x = along.normalize();
    let normal = x.cross(&(p[2] - p[0]));
    if normal.norm() < MIN_SPREAD_MM {
        return None;
    }
    let z = normal.normalize();
    let y = z.cross(&x);
    let rotation = UnitQuaternion::from_quaternion(frame::from_matrix(&Matrix3::from_columns(&[x, y, z])));
    let at = match origin {
        2 => p[1],
        3 => p[0] + x * x.dot(&(p[2] - p[0])),
        _ => p[0],
    };
    Some(Isometry3::from_parts(Translation3::from(at), rotation))
}

rapid_vm::ext::layout! {
    static DEF_FRAME: DefFrameArgs = "DefFrame" { p1: "NewP1", p2: "NewP2", p3: "NewP3", origin: "Origin" }
    static DEF_D_FRAME: DefDFrameArgs = "DefDFrame" {
        old1: "OldP1", old2: "OldP2", old3: "OldP3", new1: "NewP1", new2: "NewP2", new3: "NewP3",
    }
    static DEF_ACC_FRAME: DefAccFrameArgs = "DefAccFrame" {
        list_one: "TargetListOne", list_two: "TargetListTwo", count: "TargetsInList", max_err: "MaxErr",
        mean_err: "MeanErr",
    }
}

/// `DefFrame(NewP1, NewP2, NewP3 [\Origin])`: the frame the three points define, in
/// their own coordinate system.
// uncertain: an \Origin other than 1, 2 or 3 raises ERR_ARGVALERR.
pub(crate) fn def_frame(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *DEF_FRAME;
    let points = [point(ctx, &args[at.p1])?, point(ctx, &args[at.p2])?, point(ctx, &args[at.p3])?];
    let origin = match ctx.opt_num(args.get(at.origin))? {
        None => 1,
        Some(n) if n == 1.0 || n == 2.0 || n == 3.0 => n as u8,
        Some(_) => return Err(ctx.error(Err::ArgValue, "DefFrame \\Origin must be 1, 2 or 3")),
    };
    let frame = three_point_frame(points, origin).ok_or_else(|| frame_error(ctx))?;
    Ok(Some(frame::pose_value(ctx, &frame)?))
}

/// `DefDFrame(OldP1, OldP2, OldP3, NewP1, NewP2, NewP3)`: the displacement D with
/// NewPi = D · OldPi, from the frames each triple defines (D = F_new · F_old⁻¹).
pub(crate) fn def_d_frame(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *DEF_D_FRAME;
    let old = [point(ctx, &args[at.old1])?, point(ctx, &args[at.old2])?, point(ctx, &args[at.old3])?];
    let new = [point(ctx, &args[at.new1])?, point(ctx, &args[at.new2])?, point(ctx, &args[at.new3])?];
    let (Some(f_old), Some(f_new)) = (three_point_frame(old, 1), three_point_frame(new, 1)) else {
        return Err(frame_error(ctx));
    };
    Ok(Some(frame::pose_value(ctx, &(f_new * f_old.inverse()))?))
}

/// The first `n` robtargets of an array argument, as points.
fn point_list(ctx: &Ctx<'_>, arg: &Value, n: usize) -> Result<Vec<Vector3<f64>>, RapidError> {
    let Value::Array(array) = ctx.value(arg)? else {
        return Err(ctx.error(Err::ArgValue, "an array of robtargets was expected"));
    };
    if array.elems.len() < n {
        return Err(ctx.error(Err::ArgValue, "TargetsInList is larger than the target list"));
    }
    array.elems[..n].iter().map(|target| Ok(frame::trans_rot(ctx, target)?.0)).collect()
}

/// Whether the points spread in two directions: the second largest eigenvalue of
/// their scatter matrix is the squared spread across the best line through them.
fn spans_plane(points: &[Vector3<f64>], centre: &Vector3<f64>) -> bool {
    let scatter = points.iter().fold(Matrix3::zeros(), |acc, p| {
        let d = p - centre;
        acc + d * d.transpose()
    });
    let mut eigen: Vec<f64> = scatter.symmetric_eigenvalues().iter().copied().collect();
    eigen.sort_by(|a, b| b.total_cmp(a));
    eigen.get(1).is_some_and(|&second| second >= MIN_SPREAD_MM * MIN_SPREAD_MM)
}

fn centroid(points: &[Vector3<f64>]) -> Vector3<f64> {
    points.iter().sum::<Vector3<f64>>() / points.len() as f64
}

/// The rigid frame F that best maps `from` onto `to` (least squares, Kabsch):
/// to_i ≈ F · from_i.
fn rigid_fit(from: &[Vector3<f64>], to: &[Vector3<f64>]) -> Option<Isometry3<f64>> {
    let (c_from, c_to) = (centroid(from), centroid(to));
    if !spans_plane(from, &c_from) || !spans_plane(to, &c_to) {
        return None;
    }
    let h = from.iter().zip(to).fold(Matrix3::zeros(), |acc, (a, b)| acc + (a - c_from) * (b - c_to).transpose());
    let svd = h.svd(true, true);
    let (u, v_t) = (svd.u?, svd.v_t?);
    let v = v_t.transpose();
    // A reflection is the best fit of mirrored points; the proper rotation nearest
    // to it turns the axis of the smallest singular value round.
    let sign = (v * u.transpose()).determinant().signum();
    let r = v * Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, sign)) * u.transpose();
    let rotation = UnitQuaternion::from_quaternion(frame::from_matrix(&r));
    let t = c_to - rotation * c_from;
    Some(Isometry3::from_parts(Translation3::from(t), rotation))
}

/// `DefAccFrame(TargetListOne, TargetListTwo, TargetsInList, MaxErr, MeanErr)`: the
/// frame F with TargetListTwo{i} ≈ F · TargetListOne{i}, fitted to the first
/// TargetsInList pairs (3..10); MaxErr and MeanErr get the largest and the mean
/// distance (mm) between the moved and the fitted points.
// uncertain: a TargetsInList that is not a whole number in 3..10, or larger than a
// list, raises ERR_ARGVALERR.
pub(crate) fn def_acc_frame(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *DEF_ACC_FRAME;
    let count = ctx.num(&args[at.count])?;
    if count.fract() != 0.0 || !(3.0..=10.0).contains(&count) {
        return Err(ctx.error(Err::ArgValue, "TargetsInList must be a whole number from 3 to 10"));
    }
    let n = count as usize;
    let from = point_list(ctx, &args[at.list_one], n)?;
    let to = point_list(ctx, &args[at.list_two], n)?;
    let fit = rigid_fit(&from, &to).ok_or_else(|| frame_error(ctx))?;
    let errors: Vec<f64> = from
        .iter()
        .zip(&to)
        .map(|(a, b)| (fit * nalgebra::Point3::from(*a) - nalgebra::Point3::from(*b)).norm())
        .collect();
    let max = errors.iter().copied().fold(0.0, f64::max);
    let mean = errors.iter().sum::<f64>() / n as f64;
    ctx.store(&args[at.max_err], Value::Num(max as f32))?;
    ctx.store(&args[at.mean_err], Value::Num(mean as f32))?;
    Ok(Some(frame::pose_value(ctx, &fit)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn turn(axis: Vector3<f64>, degrees: f64) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(axis), degrees.to_radians())
    }

    #[test]
    fn a_rigid_motion_is_found_again_from_its_points() {
        // A turn about a skew axis and a shift; the fit must find them back exactly.
        let motion =
            Isometry3::from_parts(Translation3::new(12.5, -40.0, 300.0), turn(Vector3::new(1.0, 2.0, 3.0), 37.0));
        let from = [
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(250.0, 10.0, -5.0),
            Vector3::new(-30.0, 180.0, 20.0),
            Vector3::new(60.0, 70.0, 140.0),
        ];
        let to: Vec<Vector3<f64>> =
            from.iter().map(|p| motion.transform_vector(p) + motion.translation.vector).collect();
        let fit = rigid_fit(&from, &to).expect("a frame");
        assert!((fit.translation.vector - motion.translation.vector).norm() < 1e-9);
        assert!(fit.rotation.angle_to(&motion.rotation) < 1e-9);
    }

    #[test]
    fn mirrored_points_still_give_a_proper_rotation() {
        // The second list is the first mirrored in the xy plane: the best proper
        // rotation is returned, never a reflection.
        let from = [
            Vector3::new(0.0, 0.0, 10.0),
            Vector3::new(100.0, 0.0, 0.0),
            Vector3::new(0.0, 100.0, 0.0),
            Vector3::new(0.0, 0.0, 0.0),
        ];
        let to: Vec<Vector3<f64>> = from.iter().map(|p| Vector3::new(p.x, p.y, -p.z)).collect();
        let fit = rigid_fit(&from, &to).expect("a frame");
        let r = fit.rotation.to_rotation_matrix();
        assert!((r.matrix().determinant() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn points_on_a_line_give_no_frame() {
        let line: Vec<Vector3<f64>> = (0..4).map(|i| Vector3::new(f64::from(i) * 10.0, 5.0, 5.0)).collect();
        assert!(rigid_fit(&line, &line).is_none());
        assert!(three_point_frame([line[0], line[1], line[2]], 1).is_none());
    }

    #[test]
    fn three_points_give_the_frame_they_span() {
        // x from p1 towards p2 is the world's y; p3 lies on the world's -x side, so
        // z = x × (p3 - p1) = (0, 1, 0) × (-10, 0, 0) = (0, 0, 10): up, and y = z × x =
        // (-1, 0, 0). That is a quarter turn about z: q = [cos 45°, 0, 0, sin 45°].
        let p = [Vector3::new(0.0, 0.0, 0.0), Vector3::new(0.0, 10.0, 0.0), Vector3::new(-10.0, 4.0, 0.0)];
        let frame = three_point_frame(p, 1).expect("a frame");
        let half = std::f64::consts::FRAC_1_SQRT_2;
        let q = frame.rotation.into_inner();
        assert!((q.w - half).abs() < 1e-12 && q.i.abs() < 1e-12 && q.j.abs() < 1e-12 && (q.k - half).abs() < 1e-12);
        assert!(frame.translation.vector.norm() < 1e-12, "origin 1 is p1");
        // Origin 2 is p2; origin 3 is where p3 projects on the x axis: 4 mm along it.
        assert!((three_point_frame(p, 2).expect("a frame").translation.vector - p[1]).norm() < 1e-12);
        let foot = three_point_frame(p, 3).expect("a frame").translation.vector;
        assert!((foot - Vector3::new(0.0, 4.0, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn points_on_one_line_give_no_frame() {
        let p = [Vector3::new(0.0, 0.0, 0.0), Vector3::new(10.0, 0.0, 0.0), Vector3::new(30.0, 0.0, 0.0)];
        assert!(three_point_frame(p, 1).is_none());
    }
}
