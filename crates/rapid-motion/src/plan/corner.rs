//! Corner paths at fly-by points: a parabola (quadratic Bézier) from the zone
//! entry on the incoming path, with the programmed point as control point, to
//! the zone exit on the outgoing path — in TCP space between Cartesian moves,
//! per joint between joint moves and across a change of interpolation type or
//! of tool, in rotation vectors between reorientations of a standing TCP, per
//! external axis between moves of the external axes alone.

use super::orient::OriZone;
use nalgebra::{UnitQuaternion, Vector3};

use super::path::{weighted_distance, Bezier, Metric, Point, EPS_DEG, EPS_TCP};
use super::profile::EPS_LEN;
use super::segment::{axis_cap, solve_at, Prepared};
use crate::external::ExternalMove;
use crate::{Joints, Kinematics};

/// The largest turn (°) a corner path is made for; a sharper turn is close to
/// a reversal, where the parabola folds back on itself, so the point stops.
/// uncertain: what the controller does for near reversals.
const MAX_TURN: f64 = 175.0;
/// IK samples taken along a TCP corner path.
const CORNER_SAMPLES: usize = 8;

/// The curve of a corner path.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum CornerPath {
    /// Between Cartesian moves with one tool; `zone` is the position zone (mm)
    /// and `ori` the reorientation zone around it.
    Tcp { curve: Bezier<3>, ori: OriZone, zone: f64 },
    /// Between joint moves, in degrees, measured in the joint metric.
    Joint { curve: Bezier<6> },
    /// Between moves of the external axes alone: the axes' values (mm or °, weighted
    /// by their speeds) while the arm stands at `arm`.
    Axes { curve: Bezier<6>, arm: Joints },
    /// Between SingArea\Wrist moves: the TCP parabola, the wrist axes (4, 5, 6) going
    /// straight from `from` to `to` over it.
    Wrist { curve: Bezier<3>, from: [f64; 3], to: [f64; 3] },
    /// Between reorientations of a TCP standing `at`: rotation vectors (°) about the
    /// programmed orientation `point`.
    Ori { curve: Bezier<3>, at: Vector3<f64>, point: UnitQuaternion<f64> },
}

/// A planned corner between two moves.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Corner {
    pub(crate) path: CornerPath,
    /// The zone used, mm: pzone_tcp reduced to half the neighbour distances.
    pub(crate) zone: f64,
    /// Path parameter on the incoming move where the corner starts.
    pub(crate) s_in: f64,
    /// Path parameter on the outgoing move where it ends.
    pub(crate) s_out: f64,
    /// The highest speed at the corner's ends (path unit/s): lateral
    /// acceleration and axis speeds.
    pub(crate) cap: f64,
    /// The acceleration both moves allow.
    pub(crate) acc: f64,
    /// Corner-metric speed per unit of the incoming and the outgoing move's
    /// path speed: 1 unless a Cartesian move meets a joint-space corner.
    pub(crate) scale_in: f64,
    pub(crate) scale_out: f64,
    /// Joint values along the corner, keyed by the curve parameter.
    pub(crate) seeds: Vec<(f64, Joints)>,
}

/// What a corner path blends, for those who show it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CornerKind {
    /// The TCP's position (pzone_tcp).
    Tcp,
    /// The axes, in joint space (a change of interpolation or of tool).
    Joint,
    /// The orientation of a standing TCP (zone_ori).
    Orientation,
    /// The external axes, the arm standing (zone_leax, zone_reax).
    ExternalAxes,
}

impl CornerPath {
    pub(crate) fn kind(&self) -> CornerKind {
        match self {
            CornerPath::Tcp { .. } | CornerPath::Wrist { .. } => CornerKind::Tcp,
            CornerPath::Joint { .. } => CornerKind::Joint,
            CornerPath::Ori { .. } => CornerKind::Orientation,
            CornerPath::Axes { .. } => CornerKind::ExternalAxes,
        }
    }

    /// The point at curve parameter `u` (0 to 1).
    pub(crate) fn at(&self, u: f64) -> Point {
        let u = if u.is_finite() { u.clamp(0.0, 1.0) } else { 0.0 };
        match self {
            CornerPath::Tcp { curve, ori, zone } => {
                let [x, y, z] = curve.point(u);
                Point::Tcp(nalgebra::Vector3::new(x, y, z), ori.at(ori.progress_corner(u, *zone)))
            }
            CornerPath::Wrist { curve, from, to } => {
                let [x, y, z] = curve.point(u);
                Point::Wrist(nalgebra::Vector3::new(x, y, z), super::wrist::wrist_at(*from, *to, u))
            }
            CornerPath::Joint { curve } => Point::Joints(curve.point(u)),
            CornerPath::Axes { arm, .. } => Point::Joints(*arm),
            CornerPath::Ori { curve, at, point } => {
                let turn = Vector3::from(curve.point(u)).map(f64::to_radians);
                Point::Tcp(*at, point * UnitQuaternion::from_scaled_axis(turn))
            }
        }
    }

    /// The rates of the curve parameter (1/s) that give path speeds `v_in` at
    /// the entry and `v_out` at the exit: |dB/du| is twice each leg.
    pub(crate) fn rates(&self, v_in: f64, v_out: f64) -> (f64, f64) {
        let (d0, d1) = match self {
            CornerPath::Tcp { curve, .. } | CornerPath::Wrist { curve, .. } | CornerPath::Ori { curve, .. } => {
                (curve.speed(0.0), curve.speed(1.0))
            }
            CornerPath::Joint { curve } | CornerPath::Axes { curve, .. } => (curve.speed(0.0), curve.speed(1.0)),
        };
        let rate = |v: f64, d: f64| if d > 0.0 { v / d } else { 0.0 };
        (rate(v_in, d0), rate(v_out, d1))
    }

    /// The reorientation zone, for the moves on either side of a TCP corner.
    pub(crate) fn ori_zone(&self) -> Option<OriZone> {
        match self {
            CornerPath::Tcp { ori, .. } => Some(*ori),
            CornerPath::Joint { .. } | CornerPath::Axes { .. } | CornerPath::Ori { .. } | CornerPath::Wrist { .. } => {
                None
            }
        }
    }

    fn arc_length_to(&self, u: f64) -> f64 {
        match self {
            CornerPath::Tcp { curve, .. } | CornerPath::Wrist { curve, .. } | CornerPath::Ori { curve, .. } => {
                curve.length_to(u)
            }
            CornerPath::Joint { curve } | CornerPath::Axes { curve, .. } => curve.length_to(u),
        }
    }
}

/// Where a corner leaves the incoming move and joins the outgoing one.
struct Ends {
    path: CornerPath,
    s_in: f64,
    s_out: f64,
    scale_in: f64,
    scale_out: f64,
}

/// The corner between `cur` and `next`, or `None` when `cur` ends in a stop
/// point: a `fine` zone, a zone reduced to nothing, a reorientation of a standing
/// TCP or a move of the external axes alone next to a move of the TCP, a reversal,
/// or a TCP corner that leaves the robot's reach. Between Cartesian moves with one
/// tool and work object the corner is a TCP parabola; across a change of
/// interpolation type, of tool or of work object it is a joint-space parabola; between reorientations of a standing TCP, a
/// parabola of the orientation; between moves of the external axes alone, a
/// parabola of the axes (§2.2.3).
pub(crate) fn corner<K: Kinematics + ?Sized>(kin: &K, cur: &Prepared, next: &Prepared) -> Option<Corner> {
    // uncertain: a 7-axis arm (the YuMi's) stops at its fly-by points: its corner paths,
    // axis 7 blended with the arm, are not modelled yet. The path and end points are
    // the programmed ones; only the time differs (longer, as at a stop point).
    if cur.zone.is_stop() || kin.redundant() {
        return None;
    }
    // §2.2.3: no corner between a move of the TCP and one of the external axes alone.
    let (ends, zone) = match (cur.axes_only, next.axes_only) {
        (false, false) => arm_ends(kin, cur, next)?,
        (true, true) => (axes_corner(cur, next)?, 0.0),
        _ => return None,
    };
    let Ends { path, s_in, s_out, scale_in, scale_out } = ends;
    let scales_ok = [scale_in, scale_out].iter().all(|k| k.is_finite() && *k > 1e-12);
    if !scales_ok {
        return None;
    }
    let (turn, leg) = turn_and_leg(&path);
    if turn.is_nan() || turn >= MAX_TURN {
        return None;
    }
    let acc = (cur.limits.acc * scale_in).min(next.limits.acc * scale_out);
    // The blend has constant acceleration v² · sin(θ/2) / d (motion.md §4.2).
    let half = (turn / 2.0).to_radians().sin();
    let mut cap = if half > 1e-9 { (acc * leg / half).sqrt() } else { f64::INFINITY };
    let seeds = corner_seeds(kin, &path, cur, s_in)?;
    let by_length: Vec<(f64, Joints)> = seeds.iter().map(|(u, q)| (path.arc_length_to(*u), *q)).collect();
    cap = cap.min(axis_cap(&by_length, &cur.max_speeds));
    if let CornerPath::Joint { curve } | CornerPath::Axes { curve, .. } = &path {
        cap = cap.min(joint_corner_cap(curve));
    }
    Some(Corner { path, zone, s_in, s_out, cap, acc, scale_in, scale_out, seeds })
}

/// The corner between two moves of the arm, with the position zone it uses (mm).
fn arm_ends<K: Kinematics + ?Sized>(kin: &K, cur: &Prepared, next: &Prepared) -> Option<(Ends, f64)> {
    if let (Metric::Deg, Metric::Deg) = (cur.geom.metric(), next.geom.metric()) {
        return Some((ori_corner(cur, next)?, 0.0));
    }
    let (len_in, len_out) = (cur.limits.length, next.limits.length);
    // The zone may use at most half the distance to either neighbour (a zone that is
    // no positive number, which `min` would pass by, is none).
    let programmed = if cur.zone.pzone_tcp > 0.0 { cur.zone.pzone_tcp } else { 0.0 };
    let zone = programmed.min(cur.room / 2.0).min(next.room / 2.0);
    if zone.is_nan() || zone <= EPS_TCP || len_in <= EPS_LEN || len_out <= EPS_LEN {
        return None;
    }
    let ends = match (cur.geom.metric(), next.geom.metric()) {
        (Metric::Deg, _) | (_, Metric::Deg) => return None,
        (Metric::Mm, Metric::Mm) if same_tool(cur, next) && same_wobj(cur, next) => {
            match (cur.geom.wrist_interpolated(), next.geom.wrist_interpolated()) {
                (false, false) => tcp_corner(cur, next, zone)?,
                (true, true) => wrist_corner(cur, next, zone)?,
                // One keeps its orientation, the other its wrist axes: joint space.
                _ => joint_corner(kin, cur, next, zone)?,
            }
        }
        _ => joint_corner(kin, cur, next, zone)?,
    };
    Some((ends, zone))
}

/// Between two moves of the external axes alone: a parabola in the axes' values
/// from where every moving axis is within its zone of the point (zone_leax mm for a
/// linear axis, zone_reax ° for a rotating one) to where every one has left it; each
/// axis's zone is reduced to half its move on either side, as the position zone is.
// uncertain: the manual (§2.2.3) has external-axis zones work like the reorientation
// zone, but not how several axes share one corner: here it starts when the last axis
// enters its zone and ends when the first leaves its own.
fn axes_corner(cur: &Prepared, next: &Prepared) -> Option<Ends> {
    let (into, out_of) = (cur.eax.as_deref()?, next.eax.as_deref()?);
    let (mut f_in, mut f_out) = (0.5f64, 0.5f64);
    for j in 0..6 {
        let (d_in, d_out) = ((into.to[j] - into.from[j]).abs(), (out_of.to[j] - out_of.from[j]).abs());
        let linear = into.linear[j] || out_of.linear[j];
        let zone = if linear { cur.zone.zone_leax } else { cur.zone.zone_reax };
        // A zone that is no positive number leaves no room (`min` would pass a NaN by).
        let zone = if zone > 0.0 { zone } else { 0.0 };
        let zone = [d_in, d_out].into_iter().filter(|&d| d > AXIS_MOVES).fold(zone, |z, d| z.min(d / 2.0));
        if d_in > AXIS_MOVES {
            f_in = f_in.min(zone / d_in);
        }
        if d_out > AXIS_MOVES {
            f_out = f_out.min(zone / d_out);
        }
    }
    if !(f_in > EPS_LEN && f_out > EPS_LEN) {
        return None;
    }
    let weights: [f64; 6] = std::array::from_fn(|j| match into.max_speed[j].max(out_of.max_speed[j]) {
        v if v > 0.0 => 1.0 / v,
        _ => 0.0,
    });
    // The corner-metric length per unit of a move's path.
    let scale = |m: &ExternalMove, p: &Prepared| weighted_distance(&m.from, &m.to, &weights) / p.limits.length;
    let curve = Bezier::new(into.at(1.0 - f_in), into.to, out_of.at(f_out), weights);
    Some(Ends {
        path: CornerPath::Axes { curve, arm: cur.end_joints },
        s_in: cur.limits.length * (1.0 - f_in),
        s_out: next.limits.length * f_out,
        scale_in: scale(into, cur),
        scale_out: scale(out_of, next),
    })
}

/// Between two reorientations of a standing TCP: §2.2.3, without TCP movement the zone
/// is an angle (zone_ori), reduced to half of either reorientation like the position
/// zone. The orientation goes from `zone` before the point to `zone` after it on a
/// parabola of rotation vectors about the point's orientation: at its ends it turns
/// about the moves' own axes at their own speeds.
// uncertain: the shape of the controller's blend of orientations is not published.
fn ori_corner(cur: &Prepared, next: &Prepared) -> Option<Ends> {
    let (len_in, len_out) = (cur.limits.length, next.limits.length);
    // `min` would pass a NaN zone by: it must be a positive number first.
    let programmed = if cur.zone.zone_ori > 0.0 { cur.zone.zone_ori } else { 0.0 };
    let zone = programmed.min(len_in / 2.0).min(len_out / 2.0);
    if zone.is_nan() || zone <= EPS_DEG || !same_tool(cur, next) {
        return None;
    }
    let (Point::Tcp(_, from), Point::Tcp(at, point), Point::Tcp(_, to)) =
        (cur.geom.at(len_in - zone), cur.geom.at(len_in), next.geom.at(zone))
    else {
        return None;
    };
    let about_point = |r: UnitQuaternion<f64>| {
        let v = (point.inverse() * r).scaled_axis().map(f64::to_degrees);
        [v.x, v.y, v.z]
    };
    let curve = Bezier::new(about_point(from), [0.0; 3], about_point(to), [1.0; 3]);
    let path = CornerPath::Ori { curve, at, point };
    Some(Ends { path, s_in: len_in - zone, s_out: zone, scale_in: 1.0, scale_out: 1.0 })
}

/// An external axis moves when it goes further than this (mm or °).
const AXIS_MOVES: f64 = 1e-9;

fn same_tool(cur: &Prepared, next: &Prepared) -> bool {
    cur.mount.same_as(&next.mount)
}

/// §2.2.3: a corner where the coordinate system changes, a new TCP or a new work
/// object, is joint-interpolated. Work objects whose frames coincide are one.
// uncertain: the controller may compare the wobjdata rather than its frames.
fn same_wobj(cur: &Prepared, next: &Prepared) -> bool {
    super::mount::same_pose(&cur.wobj, &next.wobj)
}

/// A TCP parabola: entry `zone` mm of path before the programmed point, exit
/// `zone` mm after it.
fn tcp_corner(cur: &Prepared, next: &Prepared, zone: f64) -> Option<Ends> {
    let (len_in, s_out) = (cur.limits.length, zone);
    let s_in = len_in - zone;
    let (Point::Tcp(a, _), Point::Tcp(p, _), Point::Tcp(b, _)) =
        (cur.geom.at(s_in), cur.geom.at(len_in), next.geom.at(s_out))
    else {
        return None;
    };
    let curve = Bezier::new(a.into(), p.into(), b.into(), [1.0; 3]);
    // The reorientation zone is never smaller than the position zone, and is
    // reduced to half the neighbour distances like it (motion.md §3.2).
    // uncertain: that pzone_ori below pzone_tcp is raised to it; and the shape
    // of the blend (OriZone) is ours, the manual only says the orientation
    // heads for the next point's from the start of this zone.
    let reach = cur.zone.pzone_ori.max(zone).min(cur.room / 2.0).min(next.room / 2.0);
    let ori = OriZone {
        before: *cur.geom.ori()?,
        before_len: len_in,
        after: *next.geom.ori()?,
        after_len: next.limits.length,
        reach: if reach.is_finite() { reach } else { zone },
    };
    let path = CornerPath::Tcp { curve, ori, zone };
    Some(Ends { path, s_in, s_out, scale_in: 1.0, scale_out: 1.0 })
}

/// Between two SingArea\Wrist moves: the TCP on the parabola a TCP corner takes,
/// the wrist axes straight from where the corner leaves the one move's to where it
/// joins the other's.
fn wrist_corner(cur: &Prepared, next: &Prepared, zone: f64) -> Option<Ends> {
    let (len_in, s_out) = (cur.limits.length, zone);
    let s_in = len_in - zone;
    let (Point::Wrist(a, from), Point::Wrist(p, _), Point::Wrist(b, to)) =
        (cur.geom.at(s_in), cur.geom.at(len_in), next.geom.at(s_out))
    else {
        return None;
    };
    let curve = Bezier::new(a.into(), p.into(), b.into(), [1.0; 3]);
    Some(Ends { path: CornerPath::Wrist { curve, from, to }, s_in, s_out, scale_in: 1.0, scale_out: 1.0 })
}

/// A joint-space parabola through the programmed point's joints. On a joint
/// move the entry (exit) is the fraction of the move that the TCP zone is of
/// its TCP distance; on a Cartesian move it is `zone` mm along the path,
/// solved with IK. uncertain: the manual says only that a joint move's real
/// zone "may differ somewhat" from the programmed one.
fn joint_corner<K: Kinematics + ?Sized>(kin: &K, cur: &Prepared, next: &Prepared, zone: f64) -> Option<Ends> {
    let s_in = match cur.geom.metric() {
        Metric::Joint => cur.limits.length * (1.0 - zone / cur.room),
        _ => cur.limits.length - zone,
    };
    let s_out = match next.geom.metric() {
        Metric::Joint => next.limits.length * zone / next.room,
        _ => zone,
    };
    let weights = cur.max_speeds.map(|v| 1.0 / v);
    let (a, scale_in) = joints_and_scale(kin, cur, s_in, -1.0, &weights)?;
    let (b, scale_out) = joints_and_scale(kin, next, s_out, 1.0, &weights)?;
    let path = CornerPath::Joint { curve: Bezier::new(a, cur.end_joints, b, weights) };
    Some(Ends { path, s_in, s_out, scale_in, scale_out })
}

/// The joints at path parameter `s` of `m`, and the joint-metric length per
/// unit of `m`'s path parameter there (1 for a joint move; for a Cartesian
/// move, by a 1 mm difference towards `side`).
fn joints_and_scale<K: Kinematics + ?Sized>(
    kin: &K,
    m: &Prepared,
    s: f64,
    side: f64,
    weights: &[f64; 6],
) -> Option<(Joints, f64)> {
    let solve = |s: f64, seed: &Joints| solve_at(kin, &m.geom.at(s), &m.mount, seed).ok();
    match m.geom.at(s) {
        Point::Joints(q) => Some((q, 1.0)),
        Point::Tcp(..) | Point::Wrist(..) => {
            let q = solve(s, &nearest_seed(&m.seeds, s)?)?;
            let h = side * 1.0f64.min(m.limits.length / 4.0);
            let q2 = solve(s + h, &q)?;
            Some((q, weighted_distance(&q, &q2, weights) / h.abs()))
        }
    }
}

/// The turn angle (°) between the corner's two legs, and the shorter leg's
/// length, in the corner's metric.
fn turn_and_leg(path: &CornerPath) -> (f64, f64) {
    fn legs<const D: usize>(c: &Bezier<D>, w: &[f64; D]) -> (f64, f64) {
        let u1: Vec<f64> = (0..D).map(|k| (c.p[k] - c.a[k]) * w[k]).collect();
        let u2: Vec<f64> = (0..D).map(|k| (c.b[k] - c.p[k]) * w[k]).collect();
        let (n1, n2) = (norm(&u1), norm(&u2));
        let cos = u1.iter().zip(&u2).map(|(x, y)| x * y).sum::<f64>() / (n1 * n2);
        let turn = if cos.is_finite() { cos.clamp(-1.0, 1.0).acos().to_degrees() } else { 180.0 };
        (turn, n1.min(n2))
    }
    match path {
        CornerPath::Tcp { curve, .. } | CornerPath::Wrist { curve, .. } | CornerPath::Ori { curve, .. } => {
            legs(curve, &[1.0; 3])
        }
        CornerPath::Joint { curve } | CornerPath::Axes { curve, .. } => legs(curve, &curve.weights()),
    }
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Joint values along a TCP corner, solved from the incoming move's joints at
/// the zone entry.
fn corner_seeds<K: Kinematics + ?Sized>(
    kin: &K,
    path: &CornerPath,
    cur: &Prepared,
    s_in: f64,
) -> Option<Vec<(f64, Joints)>> {
    if let CornerPath::Joint { .. } | CornerPath::Axes { .. } = path {
        return Some(Vec::new());
    }
    let mut seed = nearest_seed(&cur.seeds, s_in)?;
    seed = solve_at(kin, &cur.geom.at(s_in), &cur.mount, &seed).ok()?;
    let mut seeds = vec![(0.0, seed)];
    for i in 1..=CORNER_SAMPLES {
        let u = i as f64 / CORNER_SAMPLES as f64;
        seed = solve_at(kin, &path.at(u), &cur.mount, &seed).ok()?;
        seeds.push((u, seed));
    }
    Some(seeds)
}

/// The seed joints stored nearest to path parameter `s`.
pub(crate) fn nearest_seed(seeds: &[(f64, Joints)], s: f64) -> Option<Joints> {
    seeds.iter().min_by(|a, b| (a.0 - s).abs().total_cmp(&(b.0 - s).abs())).map(|(_, q)| *q)
}

/// The joint-metric speed at which no axis exceeds its maximum along a joint
/// parabola: the largest share any axis takes of the tangent.
fn joint_corner_cap(curve: &Bezier<6>) -> f64 {
    let w = curve.weights();
    let mut worst = 0.0f64;
    for i in 0..=CORNER_SAMPLES {
        let u = i as f64 / CORNER_SAMPLES as f64;
        let tangent: Vec<f64> =
            (0..6).map(|k| ((1.0 - u) * (curve.p[k] - curve.a[k]) + u * (curve.b[k] - curve.p[k])) * w[k]).collect();
        let n = norm(&tangent);
        if n > 1e-12 {
            worst = worst.max(tangent.iter().fold(0.0f64, |m, x| m.max(x.abs())) / n);
        }
    }
    if worst > 0.0 {
        1.0 / worst
    } else {
        f64::INFINITY
    }
}
