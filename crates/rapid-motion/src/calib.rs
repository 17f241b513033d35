//! Calibration fits (manual §1.18): the TCP of a tool from approach poses around a
//! fixed point (MToolTCPCalib, SToolTCPCalib), a tool's orientation from elongator
//! points (MToolRotCalib, SToolRotCalib), and the frame of a rotating axis from
//! points it carried round a circle (CalcRotAxisFrame, CalcRotAxFrameZ).
//!
//! Everything is in mm and in whatever frame the caller's poses share (the robot's
//! base frame for flange poses). The controller's MaxErr and MeanErr are the largest
//! and the mean distance (mm) of each measured point from the fitted geometry.

use nalgebra::{DMatrix, DVector, Matrix3, Point3, Rotation3, UnitQuaternion, Vector3};

use crate::{MotionError, Pose};

/// The smallest singular value (relative to the largest) a TCP fit's system may have:
/// below it the approach orientations are too alike to fix the TCP.
// uncertain: the controller's own limit is not published; 1e-3 is about 0.1° of
// orientation spread per unit of TCP length.
const MIN_CONDITION: f64 = 1e-3;

/// Points closer than this (mm) count as one point; a direction shorter than this
/// is no direction.
// uncertain: the controller's tolerance is not published.
const MIN_SPREAD_MM: f64 = 0.01;

/// A fitted TCP: the tool point in the flange (or pointer) frame, the fixed point it
/// touched in the poses' frame, and the errors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TcpFit {
    /// The TCP in the frame the poses are of (tframe.trans of the tool), mm.
    pub tcp: Vector3<f64>,
    /// The fixed point all approaches met, in the poses' reference frame, mm.
    pub point: Vector3<f64>,
    /// Largest and mean distance of an approach's TCP from the fixed point, mm.
    pub max_err: f64,
    pub mean_err: f64,
}

/// Largest and mean of some distances (0 and 0 for none).
pub fn max_mean(errors: &[f64]) -> (f64, f64) {
    if errors.is_empty() {
        return (0.0, 0.0);
    }
    let max = errors.iter().copied().fold(0.0, f64::max);
    (max, errors.iter().sum::<f64>() / errors.len() as f64)
}

/// Whether `x` is a number above `limit` (NaN never is).
fn exceeds(x: f64, limit: f64) -> bool {
    x > limit
}

fn degenerate(what: &'static str) -> MotionError {
    MotionError::InvalidData(what)
}

fn finite(v: &Vector3<f64>) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The TCP that puts each pose's tool point on one fixed point, by least squares:
/// for every pose `F_i = (R_i, p_i)`, `R_i·tcp + p_i = point`. Needs at least three
/// poses whose orientations differ about two axes; otherwise the TCP is not fixed.
pub fn tcp_fit(poses: &[Pose]) -> Result<TcpFit, MotionError> {
    if poses.len() < 3 {
        return Err(degenerate("at least three approach positions are needed"));
    }
    let rows = 3 * poses.len();
    let mut a = DMatrix::<f64>::zeros(rows, 6);
    let mut b = DVector::<f64>::zeros(rows);
    for (i, pose) in poses.iter().enumerate() {
        let r = pose.rotation.to_rotation_matrix();
        let p = pose.translation.vector;
        if !finite(&p) || !r.matrix().iter().all(|x| x.is_finite()) {
            return Err(degenerate("an approach position is not a number"));
        }
        for row in 0..3 {
            for col in 0..3 {
                a[(3 * i + row, col)] = r[(row, col)];
            }
            a[(3 * i + row, 3 + row)] = -1.0;
            b[3 * i + row] = -p[row];
        }
    }
    let svd = a.svd(true, true);
    let largest = svd.singular_values.max();
    let smallest = svd.singular_values.min();
    if !exceeds(smallest, MIN_CONDITION * largest) {
        return Err(degenerate("the approach orientations are too alike to fix the TCP"));
    }
    let x = svd.solve(&b, 0.0).map_err(|_| degenerate("the TCP fit has no solution"))?;
    let tcp = Vector3::new(x[0], x[1], x[2]);
    let point = Vector3::new(x[3], x[4], x[5]);
    let errors: Vec<f64> = poses.iter().map(|f| (f.rotation * tcp + f.translation.vector - point).norm()).collect();
    let (max_err, mean_err) = max_mean(&errors);
    Ok(TcpFit { tcp, point, max_err, mean_err })
}

/// The rotation whose z axis is `z` and whose x axis is `x` made square to it.
fn frame_rotation(z: Vector3<f64>, x: Vector3<f64>) -> Result<UnitQuaternion<f64>, MotionError> {
    if !exceeds(z.norm(), MIN_SPREAD_MM) || !finite(&z) {
        return Err(degenerate("the z point coincides with the reference point"));
    }
    let z = z.normalize();
    let x = x - z * x.dot(&z);
    if !exceeds(x.norm(), MIN_SPREAD_MM * 1e-3) || !finite(&x) {
        return Err(degenerate("the x direction lies along the z axis"));
    }
    let x = x.normalize();
    let y = z.cross(&x);
    let m = Matrix3::from_columns(&[x, y, z]);
    Ok(UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m)))
}

/// MToolRotCalib: the orientation of a robot-held tool whose TCP (`tcp`, in the
/// flange frame) is known. At `ref_tip` the TCP touches a fixed tip; at `z_pos` the
/// tip lies on the tool's positive z axis; at `x_pos` on its positive x axis. Without
/// `x_pos` the tool's x axis is the flange's x axis made square to the new z.
// uncertain: the manual says only that without \XPos x and y follow tool0; squaring
// the flange x axis against z is our reading.
pub fn moving_tool_rotation(
    tcp: &Vector3<f64>,
    ref_tip: &Pose,
    z_pos: &Pose,
    x_pos: Option<&Pose>,
) -> Result<UnitQuaternion<f64>, MotionError> {
    let tip = ref_tip * Point3::from(*tcp);
    let in_flange = |pose: &Pose| (pose.inverse() * tip).coords - tcp;
    let z = in_flange(z_pos);
    let x = match x_pos {
        Some(pose) => in_flange(pose),
        None => Vector3::x(),
    };
    frame_rotation(z, x)
}

/// SToolRotCalib: the frame of a stationary tool from three points the robot's
/// pointer touched: its TCP, a point on its positive z axis and one on its positive x
/// axis (the x point is made square to z).
pub fn stationary_tool_frame(
    tcp: &Vector3<f64>,
    z_point: &Vector3<f64>,
    x_point: &Vector3<f64>,
) -> Result<Pose, MotionError> {
    let rotation = frame_rotation(z_point - tcp, x_point - tcp)?;
    Ok(Pose::from_parts((*tcp).into(), rotation))
}

/// A fitted rotation axis: its frame (origin at the centre of the circle, z along the
/// axis) and the errors (each point's distance from the fitted circle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisFit {
    pub frame: Pose,
    pub radius: f64,
    pub max_err: f64,
    pub mean_err: f64,
}

/// The circle through points a rotating axis carried round: the best plane, the best
/// circle in it. z is the plane's normal turned so that it points to the side of
/// `positive_z` when given, else so that the points, in their order, turn positively
/// about it; x points from the centre to the first point.
// uncertain: the manual does not say where CalcRotAxisFrame's x axis points, nor how
// it orients z beyond "the positive direction of the axis"; going round in list
// order is taken to be the positive direction.
pub fn rotation_axis_fit(points: &[Vector3<f64>], positive_z: Option<&Vector3<f64>>) -> Result<AxisFit, MotionError> {
    if points.len() < 3 || !points.iter().all(finite) {
        return Err(degenerate("at least three positions are needed"));
    }
    let n = points.len() as f64;
    let centroid = points.iter().sum::<Vector3<f64>>() / n;
    let normal = plane_normal(points, &centroid)?;
    // Coordinates in the plane: u along centroid→first point made square, v = n × u.
    let u0 = points[0] - centroid;
    let u = u0 - normal * u0.dot(&normal);
    if !exceeds(u.norm(), MIN_SPREAD_MM) {
        return Err(degenerate("the first position is at the centre of the others"));
    }
    let u = u.normalize();
    let v = normal.cross(&u);
    let flat: Vec<(f64, f64)> = points.iter().map(|p| ((p - centroid).dot(&u), (p - centroid).dot(&v))).collect();
    let (cu, cv, radius) = circle_2d(&flat)?;
    let centre = centroid + u * cu + v * cv;
    let z = orient_normal(normal, points, &centre, positive_z)?;
    let x = points[0] - centre;
    let rotation = frame_rotation(z, x)?;
    let errors: Vec<f64> = points
        .iter()
        .map(|p| {
            let d = p - centre;
            let height = d.dot(&z);
            let radial = (d - z * height).norm() - radius;
            (height * height + radial * radial).sqrt()
        })
        .collect();
    let (max_err, mean_err) = max_mean(&errors);
    Ok(AxisFit { frame: Pose::from_parts(centre.into(), rotation), radius, max_err, mean_err })
}

/// The unit normal of the plane that fits the points best (the direction of least
/// spread); points on a line or on one spot have none.
fn plane_normal(points: &[Vector3<f64>], centroid: &Vector3<f64>) -> Result<Vector3<f64>, MotionError> {
    let mut scatter = Matrix3::zeros();
    for p in points {
        let d = p - centroid;
        scatter += d * d.transpose();
    }
    let eigen = scatter.symmetric_eigen();
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eigen.eigenvalues[a].total_cmp(&eigen.eigenvalues[b]));
    // The middle spread must be real: else the points lie on a line (or a spot).
    let middle = eigen.eigenvalues[order[1]];
    if !exceeds(middle.sqrt(), MIN_SPREAD_MM) {
        return Err(degenerate("the positions lie on one line"));
    }
    Ok(eigen.eigenvectors.column(order[0]).into_owned().normalize())
}

/// The circle fitting points in a plane (algebraic least squares:
/// `2a·x + 2b·y + c = x² + y²`), as centre and radius.
fn circle_2d(points: &[(f64, f64)]) -> Result<(f64, f64, f64), MotionError> {
    let mut a = DMatrix::<f64>::zeros(points.len(), 3);
    let mut b = DVector::<f64>::zeros(points.len());
    for (i, &(x, y)) in points.iter().enumerate() {
        a[(i, 0)] = 2.0 * x;
        a[(i, 1)] = 2.0 * y;
        a[(i, 2)] = 1.0;
        b[i] = x * x + y * y;
    }
    let svd = a.svd(true, true);
    if !exceeds(svd.singular_values.min(), 1e-9 * svd.singular_values.max()) {
        return Err(degenerate("the positions do not define a circle"));
    }
    let s = svd.solve(&b, 0.0).map_err(|_| degenerate("the positions do not define a circle"))?;
    let r2 = s[2] + s[0] * s[0] + s[1] * s[1];
    if !exceeds(r2, 0.0) || !r2.is_finite() {
        return Err(degenerate("the positions do not define a circle"));
    }
    Ok((s[0], s[1], r2.sqrt()))
}

/// The plane normal turned to the side of `positive_z`, or so that the points turn
/// positively about it in their order.
fn orient_normal(
    normal: Vector3<f64>,
    points: &[Vector3<f64>],
    centre: &Vector3<f64>,
    positive_z: Option<&Vector3<f64>>,
) -> Result<Vector3<f64>, MotionError> {
    let side = match positive_z {
        Some(p) => {
            if !finite(p) {
                return Err(degenerate("the positive z point is not a number"));
            }
            (p - centre).dot(&normal)
        }
        None => points.windows(2).map(|w| (w[0] - centre).cross(&(w[1] - centre)).dot(&normal)).sum(),
    };
    if !exceeds(side.abs(), MIN_SPREAD_MM * 1e-3) {
        return Err(degenerate("the direction of the axis cannot be told"));
    }
    Ok(if side > 0.0 { normal } else { -normal })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robots::default_model;
    use crate::Kinematics;
    use nalgebra::{Translation3, Unit};

    fn turn(axis: Vector3<f64>, degrees: f64) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&Unit::new_normalize(axis), degrees.to_radians())
    }

    /// Four flange poses of the IRB 120 that put a known TCP on one point: the tool
    /// tilted about several axes, each pose reached through our inverse kinematics and
    /// taken back through forward kinematics (as taught jointtargets would be).
    fn approach_poses(tcp: Vector3<f64>, point: Vector3<f64>) -> Vec<Pose> {
        let kin = default_model().kinematics();
        let down = turn(Vector3::y(), 180.0);
        let tilts = [
            down,
            turn(Vector3::x(), 25.0) * down,
            turn(Vector3::y(), -30.0) * down,
            turn(Vector3::new(1.0, 1.0, 0.0), 20.0) * turn(Vector3::z(), 40.0) * down,
        ];
        tilts
            .iter()
            .map(|&r| {
                // The flange that puts the TCP on the point: p = point − R·tcp.
                let flange = Pose::from_parts(Translation3::from(point - r * tcp), r);
                let joints = kin.inverse_near(&flange, &[0.0, 0.0, 0.0, 0.0, 30.0, 0.0]).expect("reachable");
                kin.forward(&joints)
            })
            .collect()
    }

    #[test]
    fn tcp_of_four_taught_positions_is_found_again() {
        let tcp = Vector3::new(10.0, -5.0, 120.0);
        let point = Vector3::new(350.0, 50.0, 250.0);
        let fit = tcp_fit(&approach_poses(tcp, point)).expect("a fit");
        assert!((fit.tcp - tcp).norm() < 1e-6, "tcp {:?}", fit.tcp);
        assert!((fit.point - point).norm() < 1e-6);
        assert!(fit.max_err < 1e-6 && fit.mean_err < 1e-6);
    }

    #[test]
    fn one_noisy_position_bounds_the_errors() {
        // Moving one pose by 1 mm changes the right-hand side of the least-squares
        // system by a vector of length 1; the residual (the per-pose errors as a
        // vector) is its projection, so sqrt(Σe²) ≤ 1, hence MaxErr ≤ 1 and, with four
        // errors, MeanErr ≤ 2·1/4 = 0.5; and it is not zero, since no TCP fits all.
        let tcp = Vector3::new(0.0, 0.0, 150.0);
        let mut poses = approach_poses(tcp, Vector3::new(300.0, 0.0, 300.0));
        poses[2].translation.vector += Vector3::new(1.0, 0.0, 0.0);
        let fit = tcp_fit(&poses).expect("a fit");
        assert!(fit.max_err > 0.01 && fit.max_err <= 1.0 + 1e-9, "max {}", fit.max_err);
        assert!(fit.mean_err <= 0.5 + 1e-9 && fit.mean_err <= fit.max_err);
    }

    #[test]
    fn alike_orientations_fix_no_tcp() {
        let r = turn(Vector3::y(), 180.0);
        let poses: Vec<Pose> =
            (0..4).map(|i| Pose::from_parts(Translation3::new(300.0 + f64::from(i), 0.0, 300.0), r)).collect();
        assert!(tcp_fit(&poses).is_err());
        assert!(tcp_fit(&poses[..2]).is_err());
        // Turned about one axis only: the TCP along that axis is free.
        let about_z: Vec<Pose> = (0..4)
            .map(|i| Pose::from_parts(Translation3::new(0.0, 0.0, 0.0), turn(Vector3::z(), 30.0 * f64::from(i))))
            .collect();
        assert!(tcp_fit(&about_z).is_err());
    }

    #[test]
    fn moving_tool_rotation_from_elongator_points() {
        // A tool turned 90° about the flange y axis: its z is the flange's x, its x the
        // flange's −z. With the TCP at (0, 0, 100) touching a tip, moving the flange
        // back along the tool's −z by 50 mm puts the tip on the tool's +z axis.
        let tcp = Vector3::new(0.0, 0.0, 100.0);
        let tool = turn(Vector3::y(), 90.0);
        let ref_tip = Pose::from_parts(Translation3::new(400.0, 0.0, 300.0), turn(Vector3::y(), 180.0));
        let shift = |local: Vector3<f64>| {
            let mut p = ref_tip;
            p.translation.vector -= ref_tip.rotation * local;
            p
        };
        let z_pos = shift(tool * Vector3::z() * 50.0);
        let x_pos = shift(tool * Vector3::x() * 40.0);
        let rot = moving_tool_rotation(&tcp, &ref_tip, &z_pos, Some(&x_pos)).expect("a rotation");
        assert!(rot.angle_to(&tool) < 1e-9);
        // Without \XPos the flange x axis would give x, but here it lies along the
        // tool's z axis: no x direction. A z point at the reference tip: no z axis.
        assert!(moving_tool_rotation(&tcp, &ref_tip, &z_pos, None).is_err());
        assert!(moving_tool_rotation(&tcp, &ref_tip, &ref_tip, Some(&x_pos)).is_err());
    }

    #[test]
    fn stationary_frame_from_three_points() {
        let f = stationary_tool_frame(
            &Vector3::new(1000.0, 0.0, 500.0),
            &Vector3::new(1000.0, 0.0, 400.0),
            &Vector3::new(1100.0, 0.0, 480.0),
        )
        .expect("a frame");
        // z points down (−z world), x along +x world, so y = z × x = −y world: a turn
        // of 180° about x.
        assert!(f.rotation.angle_to(&turn(Vector3::x(), 180.0)) < 1e-9);
        assert_eq!(f.translation.vector, Vector3::new(1000.0, 0.0, 500.0));
    }

    #[test]
    fn circle_of_a_turning_axis() {
        // Points at radius 200 round (500, 100, 50) in a plane tilted 90° about x (the
        // axis is world −y), taken at 0°, 40°, 100°, 170° about that axis.
        let axis = turn(Vector3::x(), 90.0);
        let centre = Vector3::new(500.0, 100.0, 50.0);
        let points: Vec<Vector3<f64>> = [0.0, 40.0, 100.0, 170.0]
            .iter()
            .map(|&a: &f64| {
                centre + axis * Vector3::new(200.0 * a.to_radians().cos(), 200.0 * a.to_radians().sin(), 0.0)
            })
            .collect();
        let fit = rotation_axis_fit(&points, None).expect("a fit");
        assert!((fit.frame.translation.vector - centre).norm() < 1e-9);
        assert!((fit.radius - 200.0).abs() < 1e-9 && fit.max_err < 1e-9);
        // Turning positively about the axis in list order: z is the axis, x to point 1.
        assert!(fit.frame.rotation.angle_to(&axis) < 1e-9);
        // A positive-z point on the other side turns z round.
        let below = centre - axis * Vector3::z() * 10.0;
        let flipped = rotation_axis_fit(&points, Some(&below)).expect("a fit");
        assert!(((flipped.frame.rotation * Vector3::z()) + axis * Vector3::z()).norm() < 1e-9);
        // One point 1 mm off the plane: its error is at most 1 mm.
        let mut noisy = points.clone();
        noisy[1] += axis * Vector3::z();
        let fit = rotation_axis_fit(&noisy, None).expect("a fit");
        assert!(fit.max_err > 0.01 && fit.max_err <= 1.0 + 1e-9);
    }

    #[test]
    fn points_on_a_line_give_no_axis() {
        let line: Vec<Vector3<f64>> = (0..4).map(|i| Vector3::new(10.0 * f64::from(i), 0.0, 0.0)).collect();
        assert!(rotation_axis_fit(&line, None).is_err());
        let spot = vec![Vector3::new(1.0, 2.0, 3.0); 4];
        assert!(rotation_axis_fit(&spot, None).is_err());
        assert!(rotation_axis_fit(&line[..2], None).is_err());
    }
}
