//! What a run that moved the robot reports: the cycle time on stderr, with `--trace`
//! the trajectory as CSV or JSON (docs/trace.md), with `--report` a page of it
//! (`crate::report`). Which model moves and how the robots are set up is the
//! controller's (`rapid_controller::boot::motion`).

// The CLI is the one crate that talks to the terminal.
#![allow(clippy::print_stderr)]

use rapid_motion::plan::Sample;
use rapid_motion::Pose;
use rapid_robot::robot::{MoveFacts, RobotState};
use rapid_robot::RobotResources;
use rapid_sema::SourceInput;
use rapid_signals::IoAccess;
use rapid_syntax::LineIndex;
use rustc_hash::FxHashMap;

use crate::args::RunArgs;

/// After the run: the robot finishes its last move; the cycle time (program and
/// motion, whichever ends later, never past `limit`: the `--max-time` that stopped the
/// run) is printed unless `--quiet`, and returned. `robot_name` is the task's robot
/// (`ROB_n`), none for a positioner's task.
pub(crate) fn finish(
    resources: &mut rapid_vm::builtins::Resources,
    (program_end, limit): (f64, f64),
    (task, robot_name): (&str, Option<&str>),
    note: Option<&str>,
    args: &RunArgs,
) -> anyhow::Result<f64> {
    let motion_end = resources.robot_mut().flush();
    // Outputs the last moves set as the robot passed their points (Move*DO …).
    for (time, action) in std::mem::take(&mut resources.robot_mut().due) {
        let rapid_robot::robot::Action::Set { signal, value } = action else { continue };
        resources.io_mut().order_on_path(time.max(program_end), signal, value);
    }
    // The controller's clock has reached the end of the program and of the motion:
    // orders due by then (delayed sets, pulse ends, path events) have happened.
    resources.io_mut().advance(program_end.max(motion_end));
    // The conveyors' whole input history, for the trace of a tracking robot.
    // (The robot's state and the I/O's share the extension slot: the signals are lent.)
    let system = resources.io_mut().system.take();
    rapid_robot::robot_in(&mut resources.extensions).refresh_conveyors(system.as_ref());
    resources.io_mut().system = system;
    let robot = resources.robot_mut();
    let cycle = program_end.max(motion_end).min(limit);
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
        // A positioner's task moves its external axes only.
        let moved = match robot_name {
            Some(name) => format!("{name} {}", robot.model.name),
            None => "external axes".to_owned(),
        };
        eprintln!("cycle time {task}: {cycle:.3} s ({} moves, {moved}{failures})", robot.moves);
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
    /// The task's robot (`ROB_n`); none for a positioner's task, which moves external
    /// units only.
    pub(crate) robot_name: Option<&'a str>,
    pub(crate) cycle: f64,
}

/// Writes `--trace` and `--report`, when asked for.
pub(crate) fn write_outputs(out: &RunOutputs<'_>, args: &RunArgs) -> anyhow::Result<()> {
    if args.trace.is_none() && args.report.is_none() {
        return Ok(());
    }
    let places = move_places(out);
    if let Some(path) = &args.trace {
        crate::trace::write(out.robot, &places, path, args.sample, out.robot_name)?;
    }
    if let Some(path) = &args.report {
        crate::report::write(path, out, &places)?;
    }
    Ok(())
}

/// The trace of another motion task (MultiMove): `--trace`'s file with the task's name
/// before its extension (`trace.T_ROB2.csv`); no report. A positioner's task (no robot)
/// has its external axes' columns only.
pub(crate) fn write_task_trace(out: &RunOutputs<'_>, args: &RunArgs) -> anyhow::Result<()> {
    let Some(path) = &args.trace else { return Ok(()) };
    let path = task_trace_path(path, out.task);
    crate::trace::write(out.robot, &move_places(out), &path, args.sample, out.robot_name)
}

/// `path` with `task` before its extension: `trace.csv` → `trace.T_ROB2.csv`.
fn task_trace_path(path: &std::path::Path, task: &str) -> std::path::PathBuf {
    let stem = path.file_stem().map_or_else(Default::default, |s| s.to_string_lossy().into_owned());
    let name = match path.extension() {
        Some(ext) => format!("{stem}.{task}.{}", ext.to_string_lossy()),
        None => format!("{stem}.{task}"),
    };
    path.with_file_name(name)
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
#[derive(Clone)]
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

    /// Moves on to the facts of the move time `t` falls in (times only grow).
    pub(crate) fn advance(&mut self, t: f64) {
        let moved = self.at;
        while self.at + 1 < self.facts.len() && t >= self.facts[self.at].end && t >= self.facts[self.at + 1].start {
            self.at += 1;
        }
        if self.at != moved {
            if let Some(facts) = self.facts.get(self.at) {
                self.to_object = object_frame_inverse(facts);
            }
        }
    }

    /// The robot at `sample`, placed in the frames of the move it is on; `carry` is how
    /// far the work object it follows (a conveyor's, a unit's) had moved since the move
    /// was planned, so the TCP is placed in the object where the object is.
    pub(crate) fn locate(&mut self, sample: Sample, carry: Option<Pose>) -> Point {
        self.advance(sample.time);
        let Some(facts) = self.facts.get(self.at) else {
            return Point { sample, world: sample.tcp, object: sample.tcp, facts: None };
        };
        let frames = &facts.frames;
        let (world, object) = if frames.stationary_tool {
            // The TCP stands still; the robot carries the work object past it.
            (frames.tcp_in_world(&sample.flange), frames.tcp_in_object(&sample.flange))
        } else {
            // The planner's TCP is the tool's, in the base frame; the work object is
            // fixed in the world.
            let world = frames.base * sample.tcp;
            let object = match carry {
                Some(carry) => self.to_object * carry.inverse() * world,
                None => self.to_object * world,
            };
            (world, object)
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
