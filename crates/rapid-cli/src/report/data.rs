//! The run as the page's script sees it: the trajectory downsampled to a bounded
//! number of points, the moves' programmed points and zones, the robot's limits and
//! the signal changes, serialised to JSON inside the page.

use rapid_motion::plan::PlannedMove;
use rapid_robot::robot::{MoveFacts, RobotState};
use serde::Serialize;

use crate::motion_out::{FactsCursor, RunOutputs};

/// Most trajectory points the page holds (per series).
pub(super) const MAX_POINTS: usize = 20_000;
/// Most moves the page lists and marks.
pub(super) const MAX_MOVES: usize = 10_000;
/// Most signal changes the page draws.
const MAX_CHANGES: usize = 20_000;
/// The half width of the difference that gives the axis speeds, s.
const SPEED_H: f64 = 0.002;

/// Everything the script draws.
#[derive(Serialize)]
pub(super) struct Data {
    cycle: f64,
    /// Lower and upper limit of each axis (degrees) and its maximum speed (deg/s).
    limits: [[f64; 2]; 6],
    max_speeds: [f64; 6],
    /// The robot base's origin in the world frame, mm.
    base: [f64; 3],
    path: Series,
    /// The external axes (manifest `[[unit]]`), each with its values along the path.
    ext: Vec<ExtAxisView>,
    pub(super) moves: Vec<MoveView>,
    signals: Vec<SignalView>,
    /// Signal changes left out (beyond the bound).
    changes_cut: usize,
}

/// The downsampled trajectory, one entry per point in each vector.
#[derive(Serialize, Default)]
struct Series {
    /// Time, s.
    t: Vec<f64>,
    /// The TCP in the world frame, mm.
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
    /// TCP speed, mm/s.
    v: Vec<f64>,
    /// Axis values (degrees) and speeds (deg/s), per axis.
    j: [Vec<f64>; 6],
    jv: [Vec<f64>; 6],
    /// The index of the move the point is on (-1: none).
    m: Vec<i64>,
}

/// One external axis: its name (`UNIT eax_a`), unit, limits and maximum speed, and
/// its value and speed at each point of the path.
#[derive(Serialize)]
struct ExtAxisView {
    name: String,
    unit: &'static str,
    limits: [f64; 2],
    max_speed: f64,
    #[serde(skip)]
    index: usize,
    y: Vec<f64>,
    v: Vec<f64>,
}

/// The robot's external axes, in `eax_a` … `eax_f` order, with no points yet.
fn ext_views(robot: &rapid_robot::robot::RobotState) -> Vec<ExtAxisView> {
    let mut views: Vec<ExtAxisView> = robot
        .external
        .units
        .iter()
        .flat_map(|u| u.unit.axes.iter().map(move |a| (u.unit.name.as_str(), a)))
        .map(|(unit, a)| ExtAxisView {
            name: format!("{unit} eax_{}", char::from(b'a' + a.index() as u8)),
            unit: if a.linear { "mm" } else { "deg" },
            limits: [a.min, a.max],
            max_speed: a.max_speed,
            index: a.index(),
            y: Vec::new(),
            v: Vec::new(),
        })
        .collect();
    views.sort_by_key(|v| v.index);
    views
}

/// One move for the 3D view and the table.
#[derive(Serialize)]
pub(super) struct MoveView {
    /// The programmed point in the world frame, mm.
    p: [f64; 3],
    /// The zone the planner used, mm (0 at a stop point).
    zone: f64,
    fine: bool,
    cpf: bool,
    start: f64,
    end: f64,
}

/// One signal's step line: its value before the first change, then (time, value).
#[derive(Serialize)]
struct SignalView {
    name: String,
    first: f64,
    steps: Vec<[f64; 2]>,
}

/// `x` rounded to `decimals` decimals (short JSON, same bytes for the same run).
fn round(x: f64, decimals: i32) -> f64 {
    let scale = 10f64.powi(decimals);
    let r = (x * scale).round() / scale;
    if r.is_finite() && r != 0.0 {
        r
    } else {
        0.0
    }
}

/// The page's data for a run.
pub(super) fn collect(out: &RunOutputs<'_>) -> Data {
    let robot = out.robot;
    let model = robot.model;
    let facts = &robot.recorded_facts;
    let base = facts.first().map_or([0.0; 3], |f| {
        let b = f.frames.base.translation.vector;
        [round(b.x, 2), round(b.y, 2), round(b.z, 2)]
    });
    let (signals, changes_cut) = signals(out.io);
    let mut ext = ext_views(robot);
    let path = series(out, &mut ext);
    Data {
        cycle: round(out.cycle, 4),
        limits: model.limits.map(|(lo, hi)| [lo, hi]),
        max_speeds: model.max_speeds,
        base,
        path,
        ext,
        moves: facts.iter().take(MAX_MOVES).map(|f| move_view(robot, f)).collect(),
        signals,
        changes_cut,
    }
}

/// A move as the page shows it: its point where the robot passes it (a point on a
/// moving work object, where the object has taken it by then).
fn move_view(robot: &RobotState, f: &MoveFacts) -> MoveView {
    let p = robot.point_passed(f).translation.vector;
    MoveView {
        p: [round(p.x, 2), round(p.y, 2), round(p.z, 2)],
        zone: round(f.zone_used, 2),
        fine: f.fine,
        cpf: f.corner_path_failure,
        start: round(f.start, 4),
        end: round(f.end, 4),
    }
}

/// The trajectory at a step that keeps it within [`MAX_POINTS`]: half the points on a
/// common time grid, the rest each move's first and last sample (every k-th move's
/// when there are too many moves).
fn series(out: &RunOutputs<'_>, ext: &mut [ExtAxisView]) -> Series {
    let robot = out.robot;
    let moves: &[PlannedMove] = robot.recorded.as_deref().unwrap_or(&[]);
    let mut series = Series::default();
    let (Some(first), Some(last)) = (moves.first(), moves.last()) else { return series };
    let span = (last.end - first.start).max(0.0);
    let step = (span / (MAX_POINTS / 2) as f64).max(rapid_motion::plan::DEFAULT_STEP);
    let every = moves.len().div_ceil(MAX_POINTS / 4).max(1);
    let mut cursor = FactsCursor::new(&robot.recorded_facts);
    let mut last_t = f64::NEG_INFINITY;
    for (i, planned) in moves.iter().enumerate() {
        let ends = i % every == 0;
        let grid = planned.samples(&robot.kin, step).map(|s| s.time);
        let times = ends.then_some(planned.start).into_iter().chain(grid).chain(ends.then_some(planned.end));
        for t in times {
            // Compared as the page holds them (to 0.1 ms), so its times strictly grow.
            if round(t, 4) <= last_t || series.t.len() >= MAX_POINTS {
                continue;
            }
            last_t = round(t, 4);
            push_point(&mut series, &mut cursor, robot, planned, t);
            push_external(ext, robot, planned, t);
        }
    }
    series
}

/// One point of the series: the robot at `t` on `planned`.
fn push_point(
    series: &mut Series,
    cursor: &mut FactsCursor<'_>,
    robot: &rapid_robot::robot::RobotState,
    planned: &PlannedMove,
    t: f64,
) {
    // Where path correction and a work object the robot follows put it.
    let sample = robot.tracked(planned, robot.corrected(planned, planned.sample(&robot.kin, t)));
    let point = cursor.locate(robot.with_independent(sample, &planned.tool()), robot.carry_at(planned, t));
    let w = point.world.translation.vector;
    series.t.push(round(t, 4));
    series.x.push(round(w.x, 2));
    series.y.push(round(w.y, 2));
    series.z.push(round(w.z, 2));
    series.v.push(round(point.sample.tcp_speed, 1));
    series.m.push(point.facts.map_or(-1, |i| i as i64));
    // The axis speeds: a central difference inside the move.
    let (t1, t2) = ((t - SPEED_H).max(planned.start), (t + SPEED_H).min(planned.end));
    let (q1, q2) = (planned.sample(&robot.kin, t1).joints, planned.sample(&robot.kin, t2).joints);
    for axis in 0..6 {
        series.j[axis].push(round(point.sample.joints[axis], 3));
        let speed = if t2 - t1 > 1e-9 { (q2[axis] - q1[axis]) / (t2 - t1) } else { 0.0 };
        series.jv[axis].push(round(speed, 2));
    }
}

/// The external axes at `t` on `planned` (their values and, by a central difference,
/// their speeds); 0 when the move has no track of them.
fn push_external(ext: &mut [ExtAxisView], robot: &rapid_robot::robot::RobotState, planned: &PlannedMove, t: f64) {
    if ext.is_empty() {
        return;
    }
    let (t1, t2) = ((t - SPEED_H).max(planned.start), (t + SPEED_H).min(planned.end));
    // Axes in independent mode are where their own motion has taken them.
    let at_time = |t: f64| {
        planned.eax_at(t).map(|mut eax| {
            robot.independent.apply_eax(&mut eax, t);
            eax
        })
    };
    let (at, e1, e2) = (at_time(t), at_time(t1), at_time(t2));
    for view in ext.iter_mut() {
        let j = view.index;
        view.y.push(round(at.map_or(0.0, |e| e[j]), 3));
        let speed = match (e1, e2) {
            (Some(a), Some(b)) if t2 - t1 > 1e-9 => (b[j] - a[j]) / (t2 - t1),
            _ => 0.0,
        };
        view.v.push(round(speed, 2));
    }
}

/// Every signal's changes, in the order the signals first changed, at most
/// [`MAX_CHANGES`] in all; and how many were left out.
fn signals(io: Option<&rapid_io::IoSystem>) -> (Vec<SignalView>, usize) {
    let mut views: Vec<SignalView> = Vec::new();
    let Some(io) = io else { return (views, 0) };
    let mut rows: rustc_hash::FxHashMap<&str, usize> = rustc_hash::FxHashMap::default();
    let changes = io.changes();
    for change in changes.iter().take(MAX_CHANGES) {
        let name = change.signal.as_ref();
        let at = *rows.entry(name).or_insert_with(|| {
            views.push(SignalView { name: name.to_string(), first: round(change.old, 6), steps: Vec::new() });
            views.len() - 1
        });
        views[at].steps.push([round(change.time, 4), round(change.new, 6)]);
    }
    (views, changes.len().saturating_sub(MAX_CHANGES))
}

#[cfg(test)]
mod tests {
    use rapid_motion::plan::{MoveRequest, SpeedData, Target, ZoneData};
    use rapid_robot::robot::RobotState;

    use super::{MAX_MOVES, MAX_POINTS};
    use crate::motion_out::RunOutputs;

    /// A robot that made `n` small joint moves to stop points (axis 1 to ±1°).
    fn robot_with_moves(n: usize) -> RobotState {
        let mut robot = RobotState::new(rapid_motion::default_model());
        robot.record();
        let mut now = 0.0;
        for i in 0..n {
            let a1 = if i % 2 == 0 { 1.0 } else { -1.0 };
            let request = MoveRequest {
                target: Target::Joints([a1, 0.0, 0.0, 0.0, 30.0, 0.0]),
                speed: SpeedData::VMAX,
                zone: ZoneData::FINE,
                tool: rapid_motion::Pose::identity(),
                held_object: None,
                wobj: rapid_motion::Pose::identity(),
            };
            now = robot.push(now, &request, false, Vec::new()).expect("a reachable move");
        }
        robot
    }

    #[test]
    fn the_page_keeps_its_bounds_for_many_moves() {
        let robot = robot_with_moves(MAX_MOVES + 5);
        let sources = |_: usize| None;
        let out = RunOutputs {
            robot: &robot,
            sources: &sources,
            io: None,
            program: "many.mod".into(),
            task: "T_ROB1",
            robot_name: Some("ROB_1"),
            cycle: robot.motion_end,
        };
        let data = super::collect(&out);
        let t = &data.path.t;
        assert!(t.len() <= MAX_POINTS && t.len() > MAX_POINTS / 2, "{} points", t.len());
        assert!(t.windows(2).all(|w| w[0] < w[1]), "times grow");
        assert_eq!(data.moves.len(), MAX_MOVES);
        let places = vec![String::new(); robot.recorded_facts.len()];
        let page = super::super::html::page(&out, &places, &data).expect("a page");
        assert_eq!(page.matches("<tr class=\"move\"").count(), MAX_MOVES);
        assert!(page.contains("… 5 more moves not listed"));
    }
}
