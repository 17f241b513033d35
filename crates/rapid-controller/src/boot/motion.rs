//! The robots of a system as it starts: which model moves (`--robot`, a manifest's
//! model, else the backup's MOC.cfg robot type, else the default), where each robot's
//! base is, its axis ranges, the external units and conveyors of its task.

use rapid_robot::robot::RobotState;

use super::cell::{Cell, TaskConveyor, TaskUnit};

/// The robot model the run moves: `--robot`, else a manifest's `robot` (an unknown
/// name is an error), else the MOC.cfg robot type (a type we have no model of is an
/// error, never silently another robot), else the default. The second value is a note
/// for the user (MOC.cfg's units that are not read).
pub fn choose_model(
    robot_override: Option<&str>,
    manifest_robot: Option<&str>,
    syspar: &[(String, rapid_config::CfgFile)],
) -> Result<(&'static rapid_motion::RobotModel, Option<String>), String> {
    if let Some(name) = robot_override.or(manifest_robot) {
        let known: Vec<&str> = rapid_motion::robots::all_models().map(|m| m.name).collect();
        return rapid_motion::find_model(name)
            .map(|m| (m, None))
            .ok_or_else(|| format!("unknown robot model `{name}` (known: {})", known.join(", ")));
    }
    let moc = syspar.iter().find(|(domain, _)| domain.eq_ignore_ascii_case("MOC"));
    let (model, note) = model_of_moc(moc.map(|(_, file)| file))?;
    // The external units MOC.cfg describes in a way we cannot read: say so.
    let unread = moc.map(|(_, file)| super::moc_units::read(file).unread).unwrap_or_default();
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

/// The model MOC.cfg's (first) robot type names, else the default when MOC.cfg names
/// none. A type we have no model of is an error: moving another robot in its place
/// would give a program reach, joint values and cycle times its cell never has.
fn model_of_moc(
    moc: Option<&rapid_config::CfgFile>,
) -> Result<(&'static rapid_motion::RobotModel, Option<String>), String> {
    let typed =
        moc.and_then(|file| rapid_config::moc::robots(file).into_iter().find_map(|r| Some((r.robot_type?, r.name))));
    let default = rapid_motion::default_model();
    match typed {
        Some((ty, _)) if !rapid_motion::robots::names_a_family(&ty) => {
            // A type with no model number in it (`ROB1`) names no robot to refuse.
            // uncertain: RobotWare's own types always carry the family; such a name is
            // a hand-written or stripped configuration.
            let note =
                format!("MOC.cfg's robot type `{ty}` names no robot model; {} moved (use --robot)", default.name);
            Ok((default, Some(note)))
        }
        Some((ty, robot)) => rapid_motion::find_model(&ty).map(|m| (m, None)).ok_or_else(|| unknown_type(&ty, &robot)),
        None => Ok((default, None)),
    }
}

/// Why MOC.cfg's robot type `ty` of robot `robot` stops the run, naming the way on.
pub fn unknown_type(ty: &str, robot: &str) -> String {
    let what = match rapid_motion::robots::unsupported_family(ty) {
        Some(family) => format!("the {family}, which is not supported yet"),
        None => "a robot type we have no model of".to_owned(),
    };
    let known: Vec<&str> = rapid_motion::robots::all_models().map(|m| m.name).collect();
    format!(
        "MOC.cfg's robot {robot} is of robot type `{ty}`: {what}; no other robot is moved in its place. \
         Give the model to move with --robot (known: {})",
        known.join(", ")
    )
}

/// The model of robot ROB_`n`, which motion task `task` moves (`super::robots`):
/// `--robot`, else the task's own `robot` model in a manifest, else the manifest's
/// `[system]` robot, else its MOC.cfg robot's type (an error when we have no model of
/// it), else `system` (the run's model, [`choose_model`]).
pub fn robot_model(
    robot_override: Option<&str>,
    cell: &Cell,
    task: &str,
    n: usize,
    system: &'static rapid_motion::RobotModel,
) -> Result<&'static rapid_motion::RobotModel, String> {
    let own = cell.task_robots.iter().find(|(t, _)| t.eq_ignore_ascii_case(task)).map(|(_, m)| m);
    let named = own.and_then(|m| m.as_deref()).and_then(rapid_motion::find_model);
    // `--robot` stands above all; a manifest's [system] robot above MOC.cfg, as in
    // `choose_model`.
    if robot_override.is_some() || (named.is_none() && cell.robot.is_some()) {
        return Ok(yumi_arm_of(system, cell, n));
    }
    if let Some(model) = named {
        return Ok(model);
    }
    match moc_robot(cell.syspar, n).and_then(|r| Some((r.robot_type?, r.name))) {
        Some((ty, robot)) if rapid_motion::robots::names_a_family(&ty) => {
            rapid_motion::find_model(&ty).ok_or_else(|| unknown_type(&ty, &robot))
        }
        _ => Ok(system),
    }
}

/// The YuMi arm robot ROB_`n` is when `model` (one model for every task: `--robot
/// "IRB 14000"`) is a YuMi arm: MOC.cfg names the arms `ROB_L` and `ROB_R`, and the
/// task of ROB_L moves the left arm whichever arm the name alone gave. Any other model,
/// or a robot whose name says no side, keeps `model`.
fn yumi_arm_of(model: &'static rapid_motion::RobotModel, cell: &Cell, n: usize) -> &'static rapid_motion::RobotModel {
    use rapid_motion::kinematics::yumi::Side;
    if model.yumi.is_none() {
        return model;
    }
    let Some(robot) = moc_robot(cell.syspar, n) else { return model };
    let lower = robot.name.to_ascii_lowercase();
    let side = lower.split(['_', '-', ' ']).find_map(|part| match part {
        "l" | "left" => Some(Side::Left),
        "r" | "right" => Some(Side::Right),
        _ => None,
    });
    let Some(side) = side else { return model };
    rapid_motion::robots::yumi_arms().iter().find(|arm| arm.yumi == Some(side)).unwrap_or(model)
}

/// Sets the task's robot up for the run; with `record` (a trace or a report is
/// asked for) it records every move.
pub fn configure(robot: &mut RobotState, model: &'static rapid_motion::RobotModel, record: bool) {
    *robot = RobotState::new(model);
    if record {
        robot.record();
    }
}

/// Places robot `ROB_n`, which motion task `task` moves (`super::robots`), where the
/// manifest's `base`/`orientation` of that task puts it, else where MOC.cfg's `ROBOT`
/// instance of that name has its base frame; the world frame without either.
pub fn configure_base(robot: &mut RobotState, cell: &Cell, n: usize, task: &str) {
    let from_manifest = cell.robot_bases.iter().find(|(t, _, _)| t.eq_ignore_ascii_case(task));
    let base = match from_manifest {
        Some((_, base, orientation)) => rapid_motion::pose::pose(*base, *orientation),
        None => {
            let Some(found) = moc_robot(cell.syspar, n) else { return };
            let (pos, orient) = found.base_frame;
            rapid_motion::pose::pose(pos.map(|m| m * 1000.0), orient)
        }
    };
    robot.base_frame = base;
    robot.active.base = base;
}

/// Gives robot number `n` its MOC.cfg name when that is not `ROB_n` (`ROB_L`, `ROB_R`
/// of a two-arm system), so RobName and mecunit arguments know it by it, and puts it
/// at the cell's start axis values. Call after [`configure_ranges`]: a start outside
/// the axis ranges is refused, naming the axis.
pub fn configure_arm(robot: &mut RobotState, cell: &Cell, n: usize) -> Result<(), String> {
    if let Some(found) = moc_robot(cell.syspar, n) {
        if !found.name.eq_ignore_ascii_case(&format!("ROB_{n}")) {
            robot.name = Some(found.name);
        }
    }
    match cell.start_joints {
        Some(joints) => robot.start_at(joints),
        None => Ok(()),
    }
}

/// Narrows (or widens) the robot `ROB_n`'s axis ranges to those its backup's MOC.cfg
/// configures (`ARM -lower_joint_bound -upper_joint_bound`); the model's own elsewhere.
pub fn configure_ranges(robot: &mut RobotState, syspar: &[(String, rapid_config::CfgFile)], n: usize) {
    let Some(found) = moc_robot(syspar, n) else { return };
    if found.arm_bounds.iter().all(Option::is_none) {
        return;
    }
    let model = robot.model.limits;
    let limits =
        std::array::from_fn(|k| found.arm_bounds[k].map_or(model[k], |(lo, hi)| (lo.to_degrees(), hi.to_degrees())));
    robot.kin = robot.kin.with_limits(limits);
}

/// MOC.cfg's `ROBOT` instance of robot number `n` (`super::robots::moc_robot`).
fn moc_robot(syspar: &[(String, rapid_config::CfgFile)], n: usize) -> Option<rapid_config::moc::Robot> {
    super::robots::moc_robot(syspar, n)
}

/// Gives the robot the external units configured for its task: those naming it, and
/// for the first motion task those naming none. `task` is `None` when the run has one
/// task only (every unit is its).
pub fn configure_units(robot: &mut RobotState, units: &[TaskUnit], task: Option<&str>, first_motion: bool) {
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
pub fn configure_conveyors(
    robot: &mut RobotState,
    conveyors: &[TaskConveyor],
    io: Option<&rapid_io::IoSystem>,
    task: Option<&str>,
    first_motion: bool,
) -> Result<(), String> {
    use rapid_robot::conveyor::{Conveyor, ConveyorConfig};
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
