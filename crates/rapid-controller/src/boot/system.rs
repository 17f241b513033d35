//! Booting a system: from the tasks' loaded programs and the configuration around
//! them to a [`Controller`] ready for its start. What the tasks are (SYS.cfg's
//! `CAB_TASKS`, or one task alone), the one I/O system (EIO.cfg, `--virtual-io`'s
//! signals, a stimulus), the robot each motion task moves with its model, base, axis
//! ranges, external units and conveyors, the program operations (system inputs and
//! outputs, event routines) and the run mode.

use rapid_config::sys::{Sys, TaskType};
use rapid_config::CfgFile;
use rapid_robot::RobotResources;
use rapid_sema::SourceInput;
use rapid_signals::IoAccess;
use rapid_signals::{SharedIoAccess, SignalsVm};
use rapid_tasks::SharedTaskingAccess;
use rapid_vm::Loaded;

use super::cell::Cell;
use super::{motion, robots, virtual_io};
use crate::{Controller, TaskKind, TaskSpec, TrustLevel};

/// What a user of a YuMi must know: ABB's definition of the arm angle is not public, so
/// ours (`rapid_motion::kinematics::yumi::arm_angle`) may place the elbow elsewhere than a
/// real YuMi does for the same robtarget; the TCP pose is reached as written.
const YUMI_ARM_ANGLE: &str = "IRB 14000 YuMi: the arm angle (robtarget eax_a) follows our own reading, \
     not ABB's (not public): every TCP pose is reached as written, but axis 7 and the elbow may stand \
     elsewhere than on a real YuMi (docs/real-systems.md)";

/// A stimulus's input orders, reactions and pendant answers (`rapid_signals::io`).
pub type Stimulus = (Vec<(f64, u32, f64)>, Vec<rapid_signals::Reaction>, Vec<(f64, String)>);

/// Reads the stimulus against the system's I/O system (none when it has none); the
/// front end knows where it is and how it is written.
pub type ReadStimulus<'a> = dyn FnMut(Option<&rapid_io::IoSystem>) -> Result<Option<Stimulus>, String> + 'a;

/// How the system is to run, as the front end was asked.
#[derive(Debug, Clone, Copy, Default)]
pub struct BootOptions<'a> {
    /// One task without system inputs or outputs ([`is_alone`]): its robot is the
    /// run's model and every unit and conveyor is its own.
    pub alone: bool,
    /// The robot model asked for (`--robot`), above every configured one.
    pub robot: Option<&'a str>,
    /// The robots record every move (a trace or a report is asked for).
    pub record: bool,
    /// `--virtual-io`: every task's modules, whose AliasIO names the configuration
    /// lacks become virtual signals.
    pub virtual_io: Option<&'a [SourceInput]>,
    /// Cycles each NORMAL task runs (1: cycle mode; 0: continuous).
    pub cycles: u64,
    /// The bound on steps the front end ends the run at.
    pub max_steps: Option<u64>,
    /// The operating mode is automatic (the AutoOn system output).
    pub auto: bool,
}

/// A system ready for its start, and what its report needs.
pub struct Booted {
    pub controller: Controller,
    /// The `n` of the robot ROB_n each task moves, by task; `None`: no robot.
    pub robots: Vec<Option<usize>>,
    /// What the user should know about the model that moves (MOC.cfg names a type we
    /// have no model of, units not read).
    pub model_note: Option<String>,
}

/// Why the system cannot start.
#[derive(Debug, Clone, PartialEq)]
pub enum BootError {
    /// The system's configuration is wrong (a signal, a conveyor, a robot number…).
    Refused(String),
    /// `--robot` or a manifest names a model we do not have.
    UnknownModel(String),
    /// Our own fault: the robots could not be numbered as they were found.
    Internal(String),
}

/// Whether the inputs make a program alone: one task (`sys` configures at most one)
/// whose I/O configuration has no system inputs or outputs.
pub fn is_alone(sys: Option<&Sys>, syspar: &[(String, CfgFile)]) -> bool {
    !(sys.is_some_and(|sys| sys.tasks.len() > 1) || has_system_signals(syspar))
}

/// Whether the I/O configuration has system inputs or outputs.
pub fn has_system_signals(syspar: &[(String, CfgFile)]) -> bool {
    eio_of(syspar).is_some_and(|eio| !eio.sys_inputs.is_empty() || !eio.sys_outputs.is_empty())
}

/// The typed view of the EIO configuration, if there is one.
fn eio_of(syspar: &[(String, CfgFile)]) -> Option<rapid_config::eio::Eio> {
    let eio = syspar.iter().find(|(domain, _)| domain.eq_ignore_ascii_case("EIO"))?;
    Some(rapid_config::eio::read(&eio.1))
}

/// The tasks configuration the system runs: for a program alone, `sys` as it is
/// (its event routines); a SYS.cfg that configures no task, or none, gives the one
/// task read (`name`, starting at `entry`) as a NORMAL motion task.
pub fn system_of(sys: Option<&Sys>, alone: bool, name: &str, entry: Option<&str>) -> Option<Sys> {
    match sys {
        _ if alone => sys.cloned(),
        Some(sys) if !sys.tasks.is_empty() => Some(sys.clone()),
        Some(sys) => Some(Sys { tasks: one_task_system(name, entry).tasks, ..sys.clone() }),
        None => Some(one_task_system(name, entry)),
    }
}

/// The system of a single task without a task configuration: one NORMAL motion task.
fn one_task_system(name: &str, entry: Option<&str>) -> Sys {
    let task = rapid_config::sys::Task {
        name: name.to_owned(),
        task_type: TaskType::Normal,
        entry: entry.unwrap_or("main").to_owned(),
        entry_span: None,
        trust_level: None,
        motion_task: true,
        mechanical_unit_group: None,
        hidden: false,
        foreground: None,
        rmq: rapid_config::sys::Rmq::default(),
        line: 0,
    };
    Sys { tasks: vec![task], ..Sys::default() }
}

/// The one task of a program run alone: a NORMAL motion task moving the robot, named
/// as its backup or manifest names it.
// The configuration's type, trust level and message queue of a backup's single task
// are not applied: a program alone runs one start of its entry routine, as it always
// has under `rapid run`.
pub fn alone_spec(name: &str) -> TaskSpec {
    TaskSpec {
        name: name.to_owned(),
        kind: TaskKind::Normal,
        trust: TrustLevel::default(),
        foreground: None,
        motion: true,
        robot: true,
        rmq: rapid_config::sys::Rmq::default(),
        robot_of: None,
        shared_files: Vec::new(),
    }
}

/// The motion task whose mechanical unit group a task that is no motion task uses
/// (`-UseMechanicalUnitGroup`). A motion task without the attribute uses `rob1`, `rob2`,
/// … by its place among the motion tasks. Without the attribute, in a system of one
/// motion task (no MultiMove), the task uses that task's group, the only one.
// uncertain: both defaults; RobotWare's own configurations name the group of each
// motion task, and the attribute is needed in MultiMove systems. The second is what
// open_abb's controller backup relies on: its LOGGER task, configured without the
// attribute, streams the robot's CRobT and CJointT.
fn robot_of(sys: &Sys, task: &rapid_config::sys::Task) -> Option<String> {
    if task.motion_task {
        return None;
    }
    let mut motion = sys.tasks.iter().filter(|t| t.motion_task).enumerate();
    let Some(group) = task.mechanical_unit_group.as_deref() else {
        let only = motion.next().filter(|_| sys.tasks.iter().filter(|t| t.motion_task).count() == 1);
        return only.map(|(_, t)| t.name.clone());
    };
    let uses = |(n, t): &(usize, &rapid_config::sys::Task)| match t.mechanical_unit_group.as_deref() {
        Some(own) => own.eq_ignore_ascii_case(group),
        None => format!("rob{}", n + 1).eq_ignore_ascii_case(group),
    };
    motion.find(uses).map(|(_, t)| t.name.clone())
}

/// The tasks of SYS.cfg in configuration order.
pub fn task_specs(sys: &Sys) -> Result<Vec<TaskSpec>, String> {
    sys.tasks
        .iter()
        .map(|task| {
            let trust = match &task.trust_level {
                None => TrustLevel::default(),
                Some(text) => TrustLevel::parse(text).ok_or_else(|| {
                    format!("task {}: unknown -TrustLevel `{text}` (SysFail, SysHalt, SysStop, NoSafety)", task.name)
                })?,
            };
            let kind = match task.task_type {
                TaskType::Normal => TaskKind::Normal,
                TaskType::Static => TaskKind::Static,
                TaskType::SemiStatic => TaskKind::SemiStatic,
            };
            Ok(TaskSpec {
                name: task.name.clone(),
                kind,
                trust,
                foreground: task.foreground.clone(),
                motion: task.motion_task,
                robot: task.motion_task,
                rmq: task.rmq,
                shared_files: Vec::new(),
                robot_of: robot_of(sys, task),
            })
        })
        .collect()
}

/// Boots the system of `tasks` (their specs in configuration order, their loaded
/// programs) configured by `sys` and `cell`: its I/O system with `stimulus` (read
/// against it by the front end), its robots, its program operations. The controller
/// returned stands at power on: the front end runs the POWER_ON and START event
/// routines and then the program.
pub fn boot(
    mut tasks: Vec<(TaskSpec, Loaded)>,
    sys: Option<&Sys>,
    cell: Cell<'_>,
    options: &BootOptions<'_>,
    stimulus: &mut ReadStimulus<'_>,
) -> Result<Booted, BootError> {
    let alone = options.alone;
    let mut io = io_system(cell.syspar).map_err(BootError::Refused)?;
    if let Some(modules) = options.virtual_io {
        let mut made = with_virtual_signals(&mut io, modules).map_err(BootError::Refused)?;
        // The signals the programs name directly that no configuration defines (the
        // checker made them configured data of the type their place wants).
        if let Some(system) = io.as_mut() {
            for (_, program) in &tasks {
                let named = program.vm.configured_signals();
                made.extend(virtual_io::add_to(system, &named).map_err(BootError::Refused)?);
            }
        }
        for (_, program) in tasks.iter_mut() {
            program.vm.resources_mut().io_mut().virtual_io = true;
        }
        if let Some((_, first)) = tasks.first_mut() {
            for (name, kind) in made {
                let kind = rapid_signals::kind_name(kind);
                first.vm.resources_mut().note_later(format!("virtual signal {name} ({kind}) (--virtual-io)"));
            }
        }
    }
    let stimulus = stimulus(io.as_ref()).map_err(BootError::Refused)?;
    let (model, mut model_note) =
        motion::choose_model(options.robot, cell.robot, cell.syspar).map_err(BootError::UnknownModel)?;
    // The robot each task moves: its group's ROB_n, else by the tasks' order.
    let numbers = match sys {
        Some(sys) if !alone => robots::numbers(sys, cell.syspar, cell.task_robots)
            .map_err(|found| BootError::Refused(format!("{}.cfg:{}: {}", found.domain, found.line, found.message)))?,
        _ => vec![Some(robots::of_single_task(sys, cell.syspar, cell.task_robots))],
    };
    let mut first_motion = true;
    let mut moves_yumi = false;
    for ((spec, program), &number) in tasks.iter_mut().zip(&numbers) {
        if spec.motion {
            spec.robot = number.is_some();
            // A program alone moves the run's model; its units and conveyors are all its.
            let own = number
                .filter(|_| !alone)
                .map(|n| motion::robot_model(options.robot, &cell, &spec.name, n, model))
                .transpose()
                .map_err(BootError::UnknownModel)?;
            let task = Some(spec.name.as_str()).filter(|_| !alone);
            let robot = program.vm.resources_mut().robot_mut();
            // A task moving external units only keeps an arm that never moves (its
            // robot instructions are refused), so that its units have a state to live in.
            let moved = own.unwrap_or(model);
            moves_yumi |= moved.yumi.is_some();
            motion::configure(robot, moved, options.record);
            if let Some(n) = number {
                motion::configure_base(robot, &cell, n, &spec.name);
                motion::configure_ranges(robot, cell.syspar, n);
                motion::configure_arm(robot, &cell, n).map_err(BootError::Refused)?;
            }
            motion::configure_units(robot, cell.units, task, first_motion);
            motion::configure_conveyors(robot, cell.conveyors, io.as_ref(), task, first_motion)
                .map_err(BootError::Refused)?;
            first_motion = false;
        }
    }
    if moves_yumi {
        model_note = Some(model_note.map_or_else(|| YUMI_ARM_ANGLE.to_owned(), |n| format!("{n}; {YUMI_ARM_ANGLE}")));
    }
    // The robots work in the work objects the other tasks' units carry (MultiMove).
    if !alone {
        let mut linked: Vec<_> = tasks
            .iter_mut()
            .filter(|(spec, _)| spec.motion)
            .map(|(spec, program)| rapid_robot::foreign::LinkedTask {
                name: &spec.name,
                robot: program.vm.resources_mut().robot_mut(),
            })
            .collect();
        rapid_robot::foreign::link(&mut linked);
    }
    let mut controller = Controller::new(tasks, io).map_err(BootError::Refused)?;
    controller.set_cycles(options.cycles);
    controller.set_step_bound(options.max_steps);
    if let Err(message) = controller.shared_mut().tasking_mut().number_robots(numbers.clone()) {
        return Err(if alone { BootError::Internal(message) } else { BootError::Refused(message) });
    }
    if let Some((orders, reactions, answers)) = stimulus {
        let shared = controller.shared_mut();
        shared.io_mut().stimulus = orders.into();
        shared.io_mut().reactions = reactions;
        shared.answers = answers.into();
    }
    configure_operations(&mut controller, cell.syspar, sys, options.auto).map_err(BootError::Refused)?;
    // STOP event routines run when a task stops.
    controller.stop_routines = controller.tasks.iter().map(|t| hooks_for(sys, &t.spec.name, "STOP")).collect();
    Ok(Booted { controller, robots: numbers, model_note })
}

/// The event routines `sys` configures for `task` at system event `shelf`.
pub fn hooks_for(sys: Option<&Sys>, task: &str, shelf: &str) -> Vec<String> {
    sys.map(|sys| sys.hooks_for(task, shelf).into_iter().map(str::to_owned).collect()).unwrap_or_default()
}

/// The system inputs and outputs and the event routines of the start and of the
/// operations.
fn configure_operations(
    controller: &mut Controller,
    syspar: &[(String, CfgFile)],
    sys: Option<&Sys>,
    auto: bool,
) -> Result<(), String> {
    if let Some(eio) = eio_of(syspar) {
        controller.configure_system_signals(&eio, auto)?;
    }
    for shelf in ["POWER_ON", "STOP", "QSTOP", "RESTART", "START", "STEP"] {
        let routines = controller.tasks.iter().map(|t| hooks_for(sys, &t.spec.name, shelf)).collect();
        controller.set_event_routines(shelf, routines);
    }
    Ok(())
}

/// The I/O system of the EIO configuration (one for the whole controller).
fn io_system(syspar: &[(String, CfgFile)]) -> Result<Option<rapid_io::IoSystem>, String> {
    let eio = syspar.iter().find(|(domain, _)| domain.eq_ignore_ascii_case("EIO"));
    match eio {
        Some((_, eio)) => crate::boot::io_config::io_system(&rapid_config::eio::read(eio)).map(Some),
        None => Ok(None),
    }
}

/// `--virtual-io`: the signals AliasIO names that the configuration lacks, as virtual
/// signals (an I/O system is made when there is none).
/// Answers the signals it made.
pub fn with_virtual_signals(
    system: &mut Option<rapid_io::IoSystem>,
    modules: &[SourceInput],
) -> Result<Vec<(String, rapid_io::SignalKind)>, String> {
    let signals = virtual_io::aliased_signals(modules);
    if system.is_none() {
        *system = Some(rapid_io::IoSystem::new(Vec::new(), Vec::new()).map_err(|e| e.to_string())?);
    }
    match system {
        Some(system) => virtual_io::add_to(system, &signals),
        None => Ok(Vec::new()),
    }
}
