//! The robot around a run: which model moves (`--robot`, else the backup's MOC.cfg
//! robot type, else the default), and what a run that moved it reports: the cycle
//! time on stderr, with `--trace` the trajectory as CSV or JSON (docs/trace.md), with
//! `--report` a page of it (`crate::report`).

// The CLI is the one crate that talks to the terminal.
#![allow(clippy::print_stderr)]

use rapid_motion::plan::Sample;
use rapid_motion::Pose;
use rapid_sema::SourceInput;
use rapid_syntax::LineIndex;
use rapid_vm::builtins::motion::robot::{MoveFacts, RobotState};
use rustc_hash::FxHashMap;

use crate::args::RunArgs;

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
    // The external units MOC.cfg describes in a way we cannot read: say so.
    let unread = moc.map(|(_, file)| crate::inputs::read_moc_units(file).unread).unwrap_or_default();
    if unread.is_empty() {
        return Ok((model, note));
    }
    let units: Vec<String> = unread.iter().map(|(name, why)| format!("{name} ({why})")).collect();
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

/// The model of robot ROB_`n`, which motion task `task` moves (`crate::robots`):
/// `--robot`, else the task's own `robot` model in a manifest, else the manifest's
/// [system] robot, else its MOC.cfg robot's type when we know it, else `system` (the
/// run's model, [`choose_model`]).
pub(crate) fn robot_model(
    args: &RunArgs,
    inputs: &crate::inputs::Inputs,
    task: &str,
    n: usize,
    system: &'static rapid_motion::RobotModel,
) -> &'static rapid_motion::RobotModel {
    let own = inputs.task_robots.iter().find(|(t, _)| t.eq_ignore_ascii_case(task)).map(|(_, m)| m);
    let named = own.and_then(|m| m.as_deref()).and_then(rapid_motion::find_model);
    // `--robot` stands above all; a manifest's [system] robot above MOC.cfg, as in
    // `choose_model`.
    if args.robot.is_some() || (named.is_none() && inputs.robot.is_some()) {
        return system;
    }
    let of_moc =
        || moc_robot(&inputs.syspar, n).and_then(|r| r.robot_type).and_then(|ty| rapid_motion::find_model(&ty));
    named.or_else(of_moc).unwrap_or(system)
}

/// Sets the task's robot up for the run: a trace or a report records every move.
pub(crate) fn configure(robot: &mut RobotState, model: &'static rapid_motion::RobotModel, args: &RunArgs) {
    *robot = RobotState::new(model);
    if args.trace.is_some() || args.report.is_some() {
        robot.record();
    }
}

/// Places robot `ROB_n`, which motion task `task` moves (`crate::robots`), where the
/// manifest's `base`/`orientation` of that task puts it, else where MOC.cfg's `ROBOT`
/// instance of that name has its base frame; the world frame without either.
pub(crate) fn configure_base(robot: &mut RobotState, inputs: &crate::inputs::Inputs, n: usize, task: &str) {
    let from_manifest = inputs.robot_bases.iter().find(|(t, _, _)| t.eq_ignore_ascii_case(task));
    let base = match from_manifest {
        Some((_, base, orientation)) => rapid_motion::pose::pose(*base, *orientation),
        None => {
            let Some(found) = moc_robot(&inputs.syspar, n) else { return };
            let (pos, orient) = found.base_frame;
            rapid_motion::pose::pose(pos.map(|m| m * 1000.0), orient)
        }
    };
    robot.base_frame = base;
    robot.active.base = base;
}

/// Narrows (or widens) the robot `ROB_n`'s axis ranges to those its backup's MOC.cfg
/// configures (`ARM -lower_joint_bound -upper_joint_bound`); the model's own elsewhere.
pub(crate) fn configure_ranges(robot: &mut RobotState, syspar: &[(String, rapid_config::CfgFile)], n: usize) {
    let Some(found) = moc_robot(syspar, n) else { return };
    if found.arm_bounds.iter().all(Option::is_none) {
        return;
    }
    let model = robot.model.limits;
    let limits =
        std::array::from_fn(|k| found.arm_bounds[k].map_or(model[k], |(lo, hi)| (lo.to_degrees(), hi.to_degrees())));
    robot.kin = robot.kin.with_limits(limits);
}

/// MOC.cfg's `ROBOT` instance of robot `ROB_n`, if the system has a MOC.cfg naming it.
fn moc_robot(syspar: &[(String, rapid_config::CfgFile)], n: usize) -> Option<rapid_config::moc::Robot> {
    let (_, file) = syspar.iter().find(|(domain, _)| domain.eq_ignore_ascii_case("MOC"))?;
    let name = format!("ROB_{n}");
    rapid_config::moc::robots(file).into_iter().find(|r| r.name.eq_ignore_ascii_case(&name))
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
/// motion, whichever ends later) is printed unless `--quiet`, and returned. `robot_name`
/// is the task's robot (`ROB_n`), none for a positioner's task.
pub(crate) fn finish(
    resources: &mut rapid_vm::builtins::Resources,
    program_end: f64,
    (task, robot_name): (&str, Option<&str>),
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
