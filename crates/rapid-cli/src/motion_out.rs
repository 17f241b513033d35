//! The robot around a run: which model moves (`--robot`, else the backup's MOC.cfg
//! robot type, else the default), and what a run that moved it reports: the cycle
//! time on stderr, with `--trace` the trajectory as CSV or JSON (docs/trace.md), with
//! `--report` a page of it (`crate::report`).

// The CLI is the one crate that talks to the terminal.
#![allow(clippy::print_stderr)]

use std::fmt::Write as _;
use std::path::Path;

use rapid_motion::plan::{PlannedMove, Sample};
use rapid_motion::Pose;
use rapid_sema::SourceInput;
use rapid_syntax::LineIndex;
use rapid_vm::builtins::motion::robot::{MoveFacts, RobotState};
use rustc_hash::FxHashMap;

use crate::args::RunArgs;

/// Most trace rows written (a day at 4 ms): a bound on a mistaken `--sample`.
const MAX_TRACE_ROWS: usize = 21_600_000;

/// The robot model the run moves: `--robot`, else a manifest's `robot` (an unknown
/// name is an error), else the MOC.cfg robot type when it is a known model, else the default. The second
/// value is a note for the user when MOC.cfg names a type we have no model of.
pub(crate) fn choose_model(
    args: &RunArgs,
    manifest_robot: Option<&str>,
    syspar: &[(String, rapid_config::CfgFile)],
) -> Result<(&'static rapid_motion::RobotModel, Option<String>), String> {
    if let Some(name) = args.robot.as_deref().or(manifest_robot) {
        let known: Vec<&str> = rapid_motion::models().iter().map(|m| m.name).collect();
        return rapid_motion::find_model(name)
            .map(|m| (m, None))
            .ok_or_else(|| format!("unknown robot model `{name}` (known: {})", known.join(", ")));
    }
    let moc = syspar.iter().find(|(domain, _)| domain.eq_ignore_ascii_case("MOC"));
    let (model, note) = model_of_moc(moc.map(|(_, file)| file))?;
    // uncertain: how MOC.cfg describes an external axis (ranges, speeds, linear or
    // rotating) is not in our notes, so its units are not read: say so.
    let units = moc.map(|(_, file)| rapid_config::moc::external_units(file)).unwrap_or_default();
    if units.is_empty() {
        return Ok((model, note));
    }
    let unread = format!(
        "MOC.cfg's mechanical units {} are not read: their axes do not move (a manifest's [[unit]] configures external axes)",
        units.join(", ")
    );
    Ok((model, Some(note.map_or(unread.clone(), |n| format!("{n}; {unread}")))))
}

/// The model MOC.cfg's robot type names, else the default (with a note when the type
/// is not a model we know).
fn model_of_moc(
    moc: Option<&rapid_config::CfgFile>,
) -> Result<(&'static rapid_motion::RobotModel, Option<String>), String> {
    let robot_type = moc.and_then(|file| rapid_config::moc::robots(file).into_iter().find_map(|r| r.robot_type));
    let default = rapid_motion::default_model();
    Ok(match robot_type {
        Some(ty) => match rapid_motion::find_model(&ty) {
            Some(model) => (model, None),
            None => (
                default,
                Some(format!(
                    "MOC.cfg's robot type `{ty}` is not a model we know; {} moved (use --robot)",
                    default.name
                )),
            ),
        },
        None => (default, None),
    })
}

/// Sets the task's robot up for the run: a trace or a report records every move.
pub(crate) fn configure(robot: &mut RobotState, model: &'static rapid_motion::RobotModel, args: &RunArgs) {
    *robot = RobotState::new(model);
    if args.trace.is_some() || args.report.is_some() {
        robot.record();
    }
}

/// Gives the robot the external units configured for its task: those naming it, and
/// for the first motion task those naming none. `task` is `None` when the run has one
/// task only (every unit is its).
pub(crate) fn configure_units(
    robot: &mut RobotState,
    units: &[crate::inputs::TaskUnit],
    task: Option<&str>,
    first_motion: bool,
) {
    let mine = units.iter().filter(|u| belongs(u.task.as_deref(), task, first_motion));
    robot.configure_external(mine.map(|u| u.unit.clone()).collect());
}

/// Whether a unit or conveyor the manifest gives `named` task belongs to the run's
/// `task` (`None`: the run has one task only), the first motion task taking those
/// naming none.
fn belongs(named: Option<&str>, task: Option<&str>, first_motion: bool) -> bool {
    match (named, task) {
        (_, None) => true,
        (Some(named), Some(task)) => named.eq_ignore_ascii_case(task),
        (None, Some(_)) => first_motion,
    }
}

/// Gives the robot the conveyors configured for its task (chosen as
/// [`configure_units`] chooses units), their signals found in the I/O system: a sync
/// switch that is a digital input and a speed that is an analog input.
pub(crate) fn configure_conveyors(
    robot: &mut RobotState,
    conveyors: &[crate::inputs::TaskConveyor],
    io: Option<&rapid_io::IoSystem>,
    task: Option<&str>,
    first_motion: bool,
) -> Result<(), String> {
    use rapid_vm::builtins::motion::conveyor::{Conveyor, ConveyorConfig};
    let mine = conveyors.iter().filter(|c| belongs(c.task.as_deref(), task, first_motion));
    for c in mine {
        let signal = |name: &str, kind: rapid_io::SignalKind| -> Result<u32, String> {
            let io = io.ok_or_else(|| format!("conveyor {}: the system has no I/O configuration", c.name))?;
            match io.id(name).filter(|&id| io.def(id).is_some_and(|d| d.kind == kind)) {
                Some(id) => Ok(id),
                None => Err(format!("conveyor {}: `{name}` is no {kind:?} signal of the I/O configuration", c.name)),
            }
        };
        let (sync, speed) = (signal(&c.sync, rapid_io::SignalKind::DI)?, signal(&c.speed, rapid_io::SignalKind::AI)?);
        let base = rapid_motion::pose::pose(c.base, c.orientation);
        let config = ConveyorConfig {
            name: c.name.clone(),
            sync,
            speed,
            base,
            start_window: c.start_window,
            max_dist: c.max_dist,
        };
        let initial = io.and_then(|io| io.value(speed)).unwrap_or(0.0);
        robot.following.conveyors.push(Conveyor::new(config, initial));
        // The conveyor is a mechanical unit too (ActUnit, DeactUnit, GetNextMechUnit).
        robot.external.add_unit(rapid_motion::external::ExternalUnit {
            name: c.name.clone(),
            axes: Vec::new(),
            active_at_start: c.active,
            deactivation_forbidden: false,
            frame: None,
            carries_robot: false,
        });
    }
    Ok(())
}

/// After the run: the robot finishes its last move; the cycle time (program and
/// motion, whichever ends later) is printed unless `--quiet`, and returned.
pub(crate) fn finish(
    resources: &mut rapid_vm::builtins::Resources,
    program_end: f64,
    task: &str,
    note: Option<&str>,
    args: &RunArgs,
) -> anyhow::Result<f64> {
    let motion_end = resources.robot.flush();
    // Outputs the last moves set as the robot passed their points (Move*DO …).
    for (time, action) in std::mem::take(&mut resources.robot.due) {
        let rapid_vm::builtins::motion::robot::Action::Set { signal, value } = action else { continue };
        resources.io.order_on_path(time.max(program_end), signal, value);
    }
    // The controller's clock has reached the end of the program and of the motion:
    // orders due by then (delayed sets, pulse ends, path events) have happened.
    resources.io.advance(program_end.max(motion_end));
    // The conveyors' whole input history, for the trace of a tracking robot.
    resources.robot.refresh_conveyors(resources.io.system.as_ref());
    let robot = &mut resources.robot;
    let cycle = program_end.max(motion_end);
    if robot.moves == 0 {
        return Ok(cycle);
    }
    if !args.quiet {
        if let Some(note) = note {
            eprintln!("note: {note}");
        }
        let failures = match robot.corner_path_failures {
            0 => String::new(),
            n => format!(", {n} corner path failure(s): a fly-by point became a stop point"),
        };
        eprintln!("cycle time {task}: {cycle:.3} s ({} moves, {}{failures})", robot.moves, robot.model.name);
    }
    Ok(cycle)
}

/// What a run's trace and report are made of: the motion task's robot (taken out of
/// the finished task) and where its moves' instructions are.
pub(crate) struct RunOutputs<'a> {
    pub(crate) robot: &'a RobotState,
    /// The program file of a VM file index (the task's files, then modules loaded at
    /// run time).
    pub(crate) sources: &'a dyn Fn(usize) -> Option<&'a SourceInput>,
    /// The I/O system whose change log the report shows.
    pub(crate) io: Option<&'a rapid_io::IoSystem>,
    /// The program's name (its first file or folder), the task and the cycle time.
    pub(crate) program: String,
    pub(crate) task: &'a str,
    pub(crate) cycle: f64,
}

/// Writes `--trace` and `--report`, when asked for.
pub(crate) fn write_outputs(out: &RunOutputs<'_>, args: &RunArgs) -> anyhow::Result<()> {
    if args.trace.is_none() && args.report.is_none() {
        return Ok(());
    }
    let places = move_places(out);
    if let Some(path) = &args.trace {
        write_trace(out.robot, &places, path, args.sample)?;
    }
    if let Some(path) = &args.report {
        crate::report::write(path, out, &places)?;
    }
    Ok(())
}

/// The program's name for the report: the first path's file or folder name.
pub(crate) fn program_name(args: &RunArgs) -> String {
    let first = args.paths.first().and_then(|p| p.file_name());
    first.map_or_else(|| "program".to_string(), |name| name.to_string_lossy().into_owned())
}

/// `path:line` of each recorded move's instruction (empty when unknown), made once
/// per move rather than per sample.
fn move_places(out: &RunOutputs<'_>) -> Vec<String> {
    let mut indexes: FxHashMap<usize, LineIndex> = FxHashMap::default();
    let facts = &out.robot.recorded_facts;
    facts
        .iter()
        .map(|f| {
            let Some(input) = (out.sources)(f.file) else { return String::new() };
            let index = indexes.entry(f.file).or_insert_with(|| LineIndex::new(&input.text));
            format!("{}:{}", input.path, index.line_col(&input.text, f.span.start).line)
        })
        .collect()
}

/// A sample of the recorded trajectory with the TCP in the world frame and in the
/// move's work object, and the index of the move's facts.
pub(crate) struct Point {
    pub(crate) sample: Sample,
    pub(crate) world: Pose,
    pub(crate) object: Pose,
    pub(crate) facts: Option<usize>,
}

/// Finds the facts of the move a time falls in, for times that only grow, and places
/// the robot in that move's frames.
pub(crate) struct FactsCursor<'a> {
    facts: &'a [MoveFacts],
    at: usize,
    /// The world frame to the work object of move `at` (computed once per move).
    to_object: Pose,
}

impl<'a> FactsCursor<'a> {
    pub(crate) fn new(facts: &'a [MoveFacts]) -> FactsCursor<'a> {
        FactsCursor { facts, at: 0, to_object: facts.first().map_or(Pose::identity(), object_frame_inverse) }
    }

    /// The robot at `sample`, placed in the frames of the move it is on.
    pub(crate) fn locate(&mut self, sample: Sample) -> Point {
        let t = sample.time;
        let moved = self.at;
        while self.at + 1 < self.facts.len() && t >= self.facts[self.at].end && t >= self.facts[self.at + 1].start {
            self.at += 1;
        }
        let Some(facts) = self.facts.get(self.at) else {
            return Point { sample, world: sample.tcp, object: sample.tcp, facts: None };
        };
        if self.at != moved {
            self.to_object = object_frame_inverse(facts);
        }
        let frames = &facts.frames;
        let (world, object) = if frames.stationary_tool {
            // The TCP stands still; the robot carries the work object past it.
            (frames.tcp_in_world(&sample.flange), frames.tcp_in_object(&sample.flange))
        } else {
            // The planner's TCP is the tool's, in the base frame; the work object is
            // fixed in the world.
            let world = frames.base * sample.tcp;
            (world, self.to_object * world)
        };
        Point { sample, world, object, facts: Some(self.at) }
    }
}

/// The world frame seen from a move's work object: (user frame · object frame)⁻¹.
// uncertain: the trace's work-object pose is in the object frame without the program
// displacement (PDispOn/EOffsOn not applied), unlike CRobT, which we take to report in
// the displaced frame (FrameChain::target_of).
fn object_frame_inverse(facts: &MoveFacts) -> Pose {
    (facts.frames.uframe * facts.frames.oframe).inverse()
}

/// The trace's columns, in order.
pub(crate) const TRACE_COLUMNS: [&str; 23] = [
    "time",
    "j1",
    "j2",
    "j3",
    "j4",
    "j5",
    "j6",
    "x",
    "y",
    "z",
    "q1",
    "q2",
    "q3",
    "q4",
    "wx",
    "wy",
    "wz",
    "wq1",
    "wq2",
    "wq3",
    "wq4",
    "tcp_speed",
    "line",
];

/// The numbers of a trace row with their decimals (all columns but `line`).
fn row_numbers(p: &Point, time_decimals: u32) -> [(f64, u32); 22] {
    let s = &p.sample;
    let w = p.world.translation.vector;
    let o = p.object.translation.vector;
    let [q1, q2, q3, q4] = rapid_motion::pose::orient(&p.world);
    let [r1, r2, r3, r4] = rapid_motion::pose::orient(&p.object);
    [
        (s.time, time_decimals),
        (s.joints[0], 4),
        (s.joints[1], 4),
        (s.joints[2], 4),
        (s.joints[3], 4),
        (s.joints[4], 4),
        (s.joints[5], 4),
        (w.x, 3),
        (w.y, 3),
        (w.z, 3),
        (q1, 6),
        (q2, 6),
        (q3, 6),
        (q4, 6),
        (o.x, 3),
        (o.y, 3),
        (o.z, 3),
        (r1, 6),
        (r2, 6),
        (r3, 6),
        (r4, 6),
        (s.tcp_speed, 2),
    ]
}

/// The trajectory sampled every `sample_ms`, as CSV or (for a `.json` path) JSON,
/// written atomically (the format: docs/trace.md).
fn write_trace(robot: &RobotState, places: &[String], path: &Path, sample_ms: f64) -> anyhow::Result<()> {
    if !(sample_ms.is_finite() && sample_ms >= 0.1) {
        anyhow::bail!("--sample must be at least 0.1 ms");
    }
    let json = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let step = sample_ms / 1000.0;
    // Milliseconds while the period is whole milliseconds, else tenths of them.
    let time_decimals = if sample_ms.fract() == 0.0 { 3 } else { 4 };
    // Each move's place once, quoted for the format.
    let quoted: Vec<String> = places.iter().map(|p| if json { json_string(p) } else { csv_field(p) }).collect();
    let empty = if json { "\"\"".to_string() } else { String::new() };
    let ext = external_columns(robot);
    let columns = trace_columns(&ext);
    let head = if json { json_head(robot, sample_ms, &columns) } else { columns.join(",") + "\n" };
    crate::save::write_new_with(path, |file| {
        let mut out = head;
        let moves: &[PlannedMove] = robot.recorded.as_deref().unwrap_or(&[]);
        let mut cursor = FactsCursor::new(&robot.recorded_facts);
        let mut rows = 0;
        let mut last_eax = robot.external.start();
        for planned in moves {
            let mount = planned.tool();
            for sample in planned.samples(&robot.kin, step) {
                if rows >= MAX_TRACE_ROWS {
                    break;
                }
                // A move made with `\Corr` is where its path correction put it; an axis in
                // independent mode where its own motion took it.
                let sample = robot.tracked(planned, robot.corrected(planned, sample));
                let sample = robot.with_independent(sample, &mount);
                let point = cursor.locate(sample);
                if json {
                    out.push_str(if rows == 0 { "\n[" } else { ",\n[" });
                }
                for (value, decimals) in row_numbers(&point, time_decimals) {
                    push_number(&mut out, value, decimals, json);
                    out.push(',');
                }
                // A pause of the path keeps the axes where they were.
                last_eax = planned.eax_at(sample.time).unwrap_or(last_eax);
                robot.independent.apply_eax(&mut last_eax, sample.time);
                for &(j, _) in &ext {
                    push_number(&mut out, last_eax[j], 3, json);
                    out.push(',');
                }
                out.push_str(point.facts.and_then(|i| quoted.get(i)).unwrap_or(&empty));
                out.push_str(if json { "]" } else { "\n" });
                rows += 1;
                // Written in slices: a long trace is never held in memory whole.
                if out.len() >= TRACE_CHUNK {
                    file.write_all(out.as_bytes())?;
                    out.clear();
                }
            }
        }
        if json {
            out.push_str("\n]}\n");
        }
        file.write_all(out.as_bytes())
    })
}

/// Bytes of trace text gathered before they go to the file.
const TRACE_CHUNK: usize = 1 << 16;

/// The external axes the trace shows after `tcp_speed`: (extjoint index, column name),
/// in `eax_a` … `eax_f` order.
fn external_columns(robot: &RobotState) -> Vec<(usize, String)> {
    let mut axes: Vec<(usize, String)> = robot
        .external
        .units
        .iter()
        .flat_map(|u| &u.unit.axes)
        .map(|a| (a.index(), format!("eax_{}", char::from(b'a' + a.index() as u8))))
        .collect();
    axes.sort();
    axes
}

/// The trace's columns: [`TRACE_COLUMNS`] with the external axes before `line`.
fn trace_columns(ext: &[(usize, String)]) -> Vec<String> {
    let (line, numbers) = TRACE_COLUMNS.split_last().expect("the columns end in line");
    numbers
        .iter()
        .map(|c| c.to_string())
        .chain(ext.iter().map(|(_, name)| name.clone()))
        .chain([line.to_string()])
        .collect()
}

/// The JSON trace up to its first row: what was traced, and the columns.
fn json_head(robot: &RobotState, sample_ms: f64, columns: &[String]) -> String {
    let columns: Vec<String> = columns.iter().map(|c| json_string(c)).collect();
    format!(
        "{{\"robot\":{},\"sample_ms\":{},\"columns\":[{}],\"rows\":[",
        json_string(robot.model.name),
        serde_json::Number::from_f64(sample_ms).map_or("4".into(), |n| n.to_string()),
        columns.join(",")
    )
}

/// A number for the trace: fixed decimals; in JSON a value that is not a number is
/// `null` (JSON has no NaN).
fn push_number(out: &mut String, value: f64, decimals: u32, json: bool) {
    if json && !value.is_finite() {
        out.push_str("null");
    } else {
        push_fixed(out, value, decimals);
    }
}

/// `text` as a JSON string literal.
fn json_string(text: &str) -> String {
    serde_json::to_string(text).unwrap_or_else(|_| "\"\"".into())
}

/// `text` as a CSV field: quoted when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// `x` with `decimals` decimals, rounded, without a minus sign on zero: integer
/// arithmetic, which is many times faster than the standard exact formatting for the
/// millions of numbers of a long trace.
fn push_fixed(out: &mut String, x: f64, decimals: u32) {
    let scale = 10u64.pow(decimals);
    let scaled = (x * scale as f64).round();
    if !scaled.is_finite() || scaled.abs() >= 9.0e15 {
        let _ = write!(out, "{x:.prec$}", prec = decimals as usize);
        return;
    }
    let n = scaled as i64;
    if n < 0 {
        out.push('-');
    }
    // Digits written by hand, least significant first into a buffer: the standard
    // integer formatting costs more than the rest of a trace row.
    let mut n = n.unsigned_abs();
    let mut digits = [0u8; 24];
    let mut at = digits.len();
    for _ in 0..decimals {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
    }
    if decimals > 0 {
        at -= 1;
        digits[at] = b'.';
    }
    loop {
        at -= 1;
        digits[at] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    // Only ASCII digits and a point were written.
    out.push_str(std::str::from_utf8(&digits[at..]).unwrap_or_default());
}

#[cfg(test)]
mod tests {
    #[test]
    fn fixed_decimals_round_and_keep_zero_unsigned() {
        let mut out = String::new();
        for (x, d) in [(1.23456, 3), (-0.00004, 4), (-2.5, 2), (374.0, 3), (0.123456789, 6), (12.0, 0)] {
            super::push_fixed(&mut out, x, d);
            out.push(' ');
        }
        assert_eq!(out, "1.235 0.0000 -2.50 374.000 0.123457 12 ");
    }
}
