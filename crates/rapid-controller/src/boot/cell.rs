//! The configuration around a system's tasks that sets its robots up: the
//! configuration files (MOC.cfg: robots, bases, axis ranges, external units) and what a
//! manifest says of its robots, their bases, external units and conveyors.

use rapid_config::CfgFile;
use rapid_motion::external::ExternalUnit;

/// Every axis reaches its highest speed in this time unless the manifest gives an
/// acceleration (the arm's axes are modelled the same way).
// uncertain: ABB derives accelerations from the unit's dynamic model; not public.
pub const RAMP_TIME: f64 = 0.15;

/// A unit read from the manifest and the task it belongs to (`None`: the first
/// motion task).
#[derive(Debug, Clone, PartialEq)]
pub struct TaskUnit {
    pub task: Option<String>,
    pub unit: ExternalUnit,
}

/// A conveyor read from the manifest: its signals by name (checked against the I/O
/// configuration when the system starts) and its base frame.
#[derive(Debug, Clone, PartialEq)]
pub struct TaskConveyor {
    pub task: Option<String>,
    pub name: String,
    pub sync: String,
    pub speed: String,
    pub base: [f64; 3],
    pub orientation: [f64; 4],
    pub start_window: f64,
    pub max_dist: f64,
    /// The conveyor's mechanical unit is active when the system starts.
    pub active: bool,
}

/// What sets a system's robots up, as the inputs were read.
#[derive(Debug, Clone, Copy)]
pub struct Cell<'a> {
    /// The configuration files with their domains (`MOC`, `SYS`).
    pub syspar: &'a [(String, CfgFile)],
    /// The robot model a manifest names (`[system] robot`).
    pub robot: Option<&'a str>,
    /// A manifest's robot base frames by motion task (mm, quaternion).
    pub robot_bases: &'a [(String, [f64; 3], [f64; 4])],
    /// A manifest's robot models by motion task; `None`: the task moves no robot.
    pub task_robots: &'a [(String, Option<String>)],
    /// The external units, with their tasks.
    pub units: &'a [TaskUnit],
    /// The conveyors, with their tasks.
    pub conveyors: &'a [TaskConveyor],
    /// The axis values (degrees) every robot stands at when the system starts:
    /// `--start-joints`, else a manifest's `[system] start_joints`; the calibration
    /// position (all axes 0) without either.
    pub start_joints: Option<[f64; 6]>,
}
