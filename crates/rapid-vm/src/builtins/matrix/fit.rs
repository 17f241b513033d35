//! FitCircle (§1.15, RobotWare 6.15): the circle that best fits a set of 3D points.
//!
//! `FitCircle Points [\NumPoints] Center Radius Normal [\RMS] [\MaxErr] [\IndexWorst]`.
//! Points is an N x 3 dnum matrix, one point (x, y, z) per row; \NumPoints uses the
//! first rows only. The fit:
//! 1. the plane: through the centroid, normal to the direction in which the points
//!    spread least (the last right singular vector of the centred points);
//! 2. the circle in that plane: the algebraic least-squares fit (Kåsa), then refined
//!    by Gauss-Newton to the geometric one (least squares of the radial misses),
//!    bounded to 50 steps; both are exact for points on a circle;
//! 3. the errors: each point's distance to the circle in space (sqrt of its height
//!    above the plane squared plus its radial miss squared); \RMS is their root mean
//!    square, \MaxErr the largest, \IndexWorst its row (1-based; misses within 1e-9
//!    of each other, relatively, are a tie, which the first point wins).
//!
//! Components of the centre and normal below 1e-12 of the points' size are rounding
//! noise and reported as exactly 0.
//!
//! The normal points so that the points run counter-clockwise about it in the order
//! given (right-hand rule on the Newell sum of the polygon they form).
//!
//! uncertain: the controller's algorithm and errors are not public. Fewer than 3 points
//! or a \NumPoints outside 3..N raise ERR_ARRAY_SIZE, a matrix without 3 columns
//! ERR_INVDIM, and collinear or coincident points (no unique circle) ERR_CALC_DIVZERO.

use nalgebra::{DMatrix, DVector, Vector3};

use super::{array, block, Res};
use crate::builtins::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// Points whose second-largest spread is below this fraction of the largest lie on a line.
const COLLINEAR_TOLERANCE: f64 = 1e-9;
/// At most this many Gauss-Newton steps refine the circle (it converges in a few).
const REFINE_STEPS: usize = 50;
/// Relative difference below which two misses count as equal (\IndexWorst).
const TIE_TOLERANCE: f64 = 1e-9;
/// Relative size below which a result component is rounding noise and reported as 0.
const SNAP_TOLERANCE: f64 = 1e-12;

/// The fitted circle and how well it fits.
struct Fit {
    center: Vector3<f64>,
    radius: f64,
    normal: Vector3<f64>,
    rms: f64,
    max_err: f64,
    index_worst: usize,
}

crate::builtins::signature::layout! {
    static FIT_CIRCLE: FitCircleArgs = "FitCircle" {
        center: "Center", radius: "Radius", normal: "Normal", rms: "RMS", max_err: "MaxErr", index_worst: "IndexWorst",
    }
}

pub(super) fn fit_circle(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *FIT_CIRCLE;
    let points = read_points(ctx, args)?;
    let fit = fit(&points).ok_or_else(|| ctx.error(Err::CalcDivZero, "the points do not define a circle"))?;
    let center = pos(ctx, fit.center)?;
    let normal = pos(ctx, fit.normal)?;
    ctx.store(&args[at.center], center)?;
    ctx.store(&args[at.radius], num(ctx, fit.radius)?)?;
    ctx.store(&args[at.normal], normal)?;
    let extras = [(at.rms, fit.rms), (at.max_err, fit.max_err), (at.index_worst, (fit.index_worst + 1) as f64)];
    for (slot, value) in extras {
        if let Some(arg) = args.get(slot).filter(|a| present(Some(a))) {
            let value = num(ctx, value)?;
            ctx.store(arg, value)?;
        }
    }
    Ok(None)
}

/// The points to fit, one per row (N x 3, N >= 3).
fn read_points(ctx: &Ctx<'_>, args: &[Value]) -> Result<Vec<Vector3<f64>>, RapidError> {
    let a = array(ctx, &args[0], 2, "Points")?;
    if a.dims[1] != 3 {
        let cols = a.dims[1];
        return Err(ctx.error(Err::InvalidDim, format!("Points must have 3 columns (x, y, z), not {cols}")));
    }
    let count = match ctx.opt_num(args.get(1))? {
        None => a.dims[0] as usize,
        Some(n) if n.fract() == 0.0 && n >= 3.0 && n <= f64::from(a.dims[0]) => n as usize,
        Some(n) => return Err(ctx.error(Err::ArraySize, format!("NumPoints is {n}, outside 3 to {}", a.dims[0]))),
    };
    if count < 3 {
        return Err(ctx.error(Err::ArraySize, "FitCircle needs at least 3 points"));
    }
    let m = block(&a, count, 3);
    Ok((0..count).map(|i| Vector3::new(m[(i, 0)], m[(i, 1)], m[(i, 2)])).collect())
}

fn fit(points: &[Vector3<f64>]) -> Option<Fit> {
    let n = points.len() as f64;
    let centroid = points.iter().sum::<Vector3<f64>>() / n;
    let centred = DMatrix::from_fn(points.len(), 3, |i, j| points[i][j] - centroid[j]);
    let svd = nalgebra::SVD::try_new(centred, false, true, f64::EPSILON, 100_000)?;
    let v_t = svd.v_t?;
    let s = svd.singular_values;
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| s[j].total_cmp(&s[i]));
    if s[order[0]] == 0.0 || s[order[1]] <= COLLINEAR_TOLERANCE * s[order[0]] {
        return None;
    }
    let axis = |k: usize| Vector3::new(v_t[(order[k], 0)], v_t[(order[k], 1)], v_t[(order[k], 2)]);
    let u = axis(0).normalize();
    let mut normal = axis(2).normalize();
    if newell(points, &centroid).dot(&normal) < 0.0 {
        normal = -normal;
    }
    let w = normal.cross(&u);
    let flat: Vec<(f64, f64)> = points.iter().map(|p| ((p - centroid).dot(&u), (p - centroid).dot(&w))).collect();
    let (a, b, radius) = refine(&flat, kasa(&flat)?);
    let center = centroid + u * a + w * b;
    let errors: Vec<f64> = points.iter().map(|p| distance_to_circle(p, &center, &normal, radius)).collect();
    let rms = (errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt();
    let max_err = errors.iter().copied().fold(0.0, f64::max);
    // Misses equal up to rounding count as a tie, which the first point wins.
    let index_worst = errors.iter().position(|&e| e >= max_err * (1.0 - TIE_TOLERANCE)).unwrap_or(0);
    // Components that are zero up to rounding are reported as zero, not as -1e-16.
    let scale = points.iter().map(|p| p.amax()).fold(1.0, f64::max);
    let center = center.map(|x| snap(x, scale));
    let normal = normal.map(|x| snap(x, 1.0));
    Some(Fit { center, radius, normal, rms, max_err, index_worst })
}

/// `x`, or 0 when it is below the rounding noise of values of size `scale`.
fn snap(x: f64, scale: f64) -> f64 {
    if x.abs() <= SNAP_TOLERANCE * scale {
        0.0
    } else {
        x
    }
}

/// The Newell sum: twice the area vector of the closed polygon through the points.
fn newell(points: &[Vector3<f64>], centroid: &Vector3<f64>) -> Vector3<f64> {
    let next = points.iter().cycle().skip(1);
    points.iter().zip(next).map(|(p, q)| (p - centroid).cross(&(q - centroid))).sum()
}

/// A circle in the plane: centre (a, b) and radius.
type Circle2 = (f64, f64, f64);

/// The algebraic fit in the plane: least squares on `2a x + 2b y + k = x^2 + y^2`,
/// giving the centre (a, b) and radius sqrt(k + a^2 + b^2).
fn kasa(flat: &[(f64, f64)]) -> Option<Circle2> {
    let m = DMatrix::from_fn(flat.len(), 3, |i, j| match j {
        0 => 2.0 * flat[i].0,
        1 => 2.0 * flat[i].1,
        _ => 1.0,
    });
    let rhs = DVector::from_fn(flat.len(), |i, _| flat[i].0 * flat[i].0 + flat[i].1 * flat[i].1);
    let svd = nalgebra::SVD::try_new(m, true, true, f64::EPSILON, 100_000)?;
    let largest = svd.singular_values.max();
    let solution = svd.solve(&rhs, largest * 1e-12).ok()?;
    let (a, b, k) = (solution[0], solution[1], solution[2]);
    let r2 = k + a * a + b * b;
    (r2 > 0.0 && r2.is_finite()).then(|| (a, b, r2.sqrt()))
}

/// Sum of squared radial misses of the points from a circle in the plane.
fn radial_cost(flat: &[(f64, f64)], (a, b, r): Circle2) -> f64 {
    flat.iter().map(|&(x, y)| ((x - a).hypot(y - b) - r).powi(2)).sum()
}

/// The geometric fit in the plane: Gauss-Newton on the radial misses, from the
/// algebraic fit, taking a step only while it lowers their sum of squares (so the
/// result is never worse than the start), at most `REFINE_STEPS` steps.
fn refine(flat: &[(f64, f64)], start: Circle2) -> Circle2 {
    let mut best = start;
    let mut cost = radial_cost(flat, best);
    for _ in 0..REFINE_STEPS {
        let (a, b, r) = best;
        if flat.iter().any(|&(x, y)| (x - a).hypot(y - b) == 0.0) {
            break;
        }
        let jacobian = DMatrix::from_fn(flat.len(), 3, |i, j| {
            let (x, y) = flat[i];
            let rho = (x - a).hypot(y - b);
            match j {
                0 => -(x - a) / rho,
                1 => -(y - b) / rho,
                _ => -1.0,
            }
        });
        let residual = DVector::from_fn(flat.len(), |i, _| (flat[i].0 - a).hypot(flat[i].1 - b) - r);
        let Some(svd) = nalgebra::SVD::try_new(jacobian, true, true, f64::EPSILON, 100_000) else { break };
        let Ok(step) = svd.solve(&-residual, 1e-12) else { break };
        let next = (a + step[0], b + step[1], r + step[2]);
        let next_cost = radial_cost(flat, next);
        if next_cost.is_nan() || next_cost >= cost || next.2 <= 0.0 {
            break;
        }
        best = next;
        cost = next_cost;
    }
    best
}

/// The distance in space from `p` to the circle.
fn distance_to_circle(p: &Vector3<f64>, center: &Vector3<f64>, normal: &Vector3<f64>, radius: f64) -> f64 {
    let d = p - center;
    let height = d.dot(normal);
    let radial = (d - normal * height).norm();
    (height * height + (radial - radius) * (radial - radius)).sqrt()
}

/// A num result (an IEEE single); outside its range is ERR_NUM_LIMIT.
fn single(ctx: &Ctx<'_>, x: f64) -> Result<f32, RapidError> {
    let single = x as f32;
    if !single.is_finite() {
        return Err(ctx.error(Err::NumLimit, "a FitCircle result is outside the range of num"));
    }
    Ok(single + 0.0)
}

fn num(ctx: &Ctx<'_>, x: f64) -> Result<Value, RapidError> {
    single(ctx, x).map(Value::Num)
}

fn pos(ctx: &Ctx<'_>, v: Vector3<f64>) -> Result<Value, RapidError> {
    Ok(ctx.pos(single(ctx, v.x)?, single(ctx, v.y)?, single(ctx, v.z)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_points_on_a_tilted_circle() {
        // Radius 5 about (1, 2, 3) in the plane z = 3, counter-clockwise seen from +z.
        let pts: Vec<Vector3<f64>> =
            [(6.0, 2.0), (1.0, 7.0), (-4.0, 2.0), (1.0, -3.0)].iter().map(|&(x, y)| Vector3::new(x, y, 3.0)).collect();
        let fit = fit(&pts).expect("a circle");
        assert!((fit.radius - 5.0).abs() < 1e-9);
        assert!((fit.center - Vector3::new(1.0, 2.0, 3.0)).norm() < 1e-9);
        assert!((fit.normal - Vector3::new(0.0, 0.0, 1.0)).norm() < 1e-9);
        assert!(fit.rms < 1e-9);
    }

    #[test]
    fn refinement_lowers_the_radial_misses_of_a_noisy_arc() {
        // A quarter arc of radius 10 with alternating misses: the algebraic fit is
        // biased there; the refinement lowers the misses and reaches a stationary point.
        let flat: Vec<(f64, f64)> = (0..7)
            .map(|i| {
                let t = f64::from(i) * std::f64::consts::FRAC_PI_2 / 6.0;
                let r = if i % 2 == 0 { 10.3 } else { 9.7 };
                (r * t.cos(), r * t.sin())
            })
            .collect();
        let start = kasa(&flat).expect("a circle");
        let refined = refine(&flat, start);
        assert!(radial_cost(&flat, refined) <= radial_cost(&flat, start));
        assert!(radial_cost(&flat, refined) < radial_cost(&flat, start));
        // The geometric optimum: the gradient of the cost, J^T r, vanishes there.
        let (a, b, r) = refined;
        let mut gradient = [0.0_f64; 3];
        for &(x, y) in &flat {
            let rho = (x - a).hypot(y - b);
            let miss = rho - r;
            gradient[0] -= miss * (x - a) / rho;
            gradient[1] -= miss * (y - b) / rho;
            gradient[2] -= miss;
        }
        assert!(gradient.iter().all(|g| g.abs() < 1e-9), "gradient {gradient:?}");
    }

    #[test]
    fn collinear_points_have_no_circle() {
        let pts = vec![Vector3::new(0.0, 0.0, 0.0), Vector3::new(1.0, 1.0, 1.0), Vector3::new(2.0, 2.0, 2.0)];
        assert!(fit(&pts).is_none());
    }
}
