//! The robot around a run: which model moves (`--robot`, else the backup's MOC.cfg
//! robot type, else the default), and what a run that moved it reports: the cycle
//! time on stderr and, with `--trace`, the trajectory as CSV.

// The CLI is the one crate that talks to the terminal.
#![allow(clippy::print_stderr)]

use std::fmt::Write as _;
use std::path::Path;

use rapid_motion::plan::PlannedMove;
use rapid_vm::builtins::motion::robot::RobotState;

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
    let robot_type = moc.and_then(|(_, file)| rapid_config::moc::robots(file).into_iter().find_map(|r| r.robot_type));
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

/// Sets the task's robot up for the run.
pub(crate) fn configure(robot: &mut RobotState, model: &'static rapid_motion::RobotModel, args: &RunArgs) {
    *robot = RobotState::new(model);
    if args.trace.is_some() {
        robot.record();
    }
}

/// After the run: the robot finishes its last move; the cycle time (program and
/// motion, whichever ends later) is printed unless `--quiet`, and the trace written.
pub(crate) fn finish(
    resources: &mut rapid_vm::builtins::Resources,
    program_end: f64,
    task: &str,
    note: Option<&str>,
    args: &RunArgs,
) -> anyhow::Result<()> {
    let motion_end = resources.robot.flush();
    // Outputs the last moves set as the robot passed their points (Move*DO …).
    for (time, action) in std::mem::take(&mut resources.robot.due) {
        let rapid_vm::builtins::motion::robot::Action::Set { signal, value } = action else { continue };
        resources.io.order_on_path(time.max(program_end), signal, value);
    }
    // The controller's clock has reached the end of the program and of the motion:
    // orders due by then (delayed sets, pulse ends, path events) have happened.
    resources.io.advance(program_end.max(motion_end));
    let robot = &mut resources.robot;
    if robot.moves == 0 {
        return Ok(());
    }
    if !args.quiet {
        if let Some(note) = note {
            eprintln!("note: {note}");
        }
        let cycle = program_end.max(motion_end);
        let failures = match robot.corner_path_failures {
            0 => String::new(),
            n => format!(", {n} corner path failure(s): a fly-by point became a stop point"),
        };
        eprintln!("cycle time {task}: {cycle:.3} s ({} moves, {}{failures})", robot.moves, robot.model.name);
    }
    if let Some(path) = &args.trace {
        write_trace(robot, path, args.sample)?;
    }
    Ok(())
}

/// The trajectory sampled every `sample_ms`, as CSV, written atomically.
fn write_trace(robot: &RobotState, path: &Path, sample_ms: f64) -> anyhow::Result<()> {
    if !(sample_ms.is_finite() && sample_ms >= 0.1) {
        anyhow::bail!("--sample must be at least 0.1 ms");
    }
    let step = sample_ms / 1000.0;
    let mut csv = String::from("time,j1,j2,j3,j4,j5,j6,x,y,z,q1,q2,q3,q4,tcp_speed\n");
    let moves: &[PlannedMove] = robot.recorded.as_deref().unwrap_or(&[]);
    let mut rows = 0;
    for planned in moves {
        for s in planned.samples(&robot.kin, step) {
            if rows >= MAX_TRACE_ROWS {
                break;
            }
            let t = s.tcp.translation.vector;
            let [q1, q2, q3, q4] = rapid_motion::pose::orient(&s.tcp);
            let fields = [
                (s.time, 3),
                (s.joints[0], 4),
                (s.joints[1], 4),
                (s.joints[2], 4),
                (s.joints[3], 4),
                (s.joints[4], 4),
                (s.joints[5], 4),
                (t.x, 3),
                (t.y, 3),
                (t.z, 3),
                (q1, 6),
                (q2, 6),
                (q3, 6),
                (q4, 6),
                (s.tcp_speed, 2),
            ];
            for (k, (value, decimals)) in fields.into_iter().enumerate() {
                if k > 0 {
                    csv.push(',');
                }
                push_fixed(&mut csv, value, decimals);
            }
            csv.push('\n');
            rows += 1;
        }
    }
    crate::save::write_new(path, csv.as_bytes())
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
    let n = n.unsigned_abs();
    let _ = write!(out, "{}", n / scale);
    if decimals > 0 {
        let _ = write!(out, ".{:0width$}", n % scale, width = decimals as usize);
    }
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
