//! The motion configuration (`MOC.cfg`), as far as programs see it: the robots and the
//! robot types they use (`ROBOT: -name "ROB_1" -use_robot_type "ROB1"`), and the external
//! mechanical units with their axes as the file links them.

use crate::CfgFile;

/// One `ROBOT` instance.
#[derive(Debug, Clone, PartialEq)]
pub struct Robot {
    pub name: String,
    /// `-use_robot_type`: the name of the `ROBOT_TYPE` instance.
    pub robot_type: Option<String>,
    pub line: u32,
    /// The robot's base frame in the world: `-base_frame_pos_x/y/z` (metres) and
    /// `-base_frame_orient_u0` … `u3` (a unit quaternion, u0 the scalar part); the world
    /// frame itself where they are absent.
    pub base_frame: ([f64; 3], [f64; 4]),
    /// Each axis's working range as configured, radians: the `ARM` of the joint
    /// `-use_joint_0` … `-use_joint_5` names (through the `JOINT`'s `-use_arm` where
    /// there is one, else the `ARM` of the joint's own name, as RobotWare names them).
    pub arm_bounds: [Option<(f64, f64)>; 6],
}

/// The robots of a MOC file.
pub fn robots(file: &CfgFile) -> Vec<Robot> {
    file.instances("ROBOT")
        .filter_map(|inst| {
            let name = inst.name()?;
            let robot_type = inst.value("use_robot_type").map(str::to_owned);
            let base_frame = base_frame(inst);
            let arm_bounds = std::array::from_fn(|k| arm_bounds(file, inst.value(&format!("use_joint_{k}"))?));
            Some(Robot { name: name.to_owned(), robot_type, line: inst.line, base_frame, arm_bounds })
        })
        .collect()
}

/// The working range of the `ARM` of a robot joint, radians.
fn arm_bounds(file: &CfgFile, joint: &str) -> Option<(f64, f64)> {
    let arm = named(file, "JOINT", joint).and_then(|j| j.value("use_arm")).unwrap_or(joint);
    let lower = number(file, "ARM", Some(arm), "lower_joint_bound")?;
    let upper = number(file, "ARM", Some(arm), "upper_joint_bound")?;
    (lower < upper).then_some((lower, upper))
}

/// An instance's base frame attributes (ROBOT, SINGLE): position in metres, orientation
/// as a quaternion; absent values are those of the identity.
fn base_frame(inst: &crate::Instance) -> ([f64; 3], [f64; 4]) {
    let value = |attr: &str, default: f64| parsed(inst, attr).unwrap_or(default);
    let pos = ["x", "y", "z"].map(|c| value(&format!("base_frame_pos_{c}"), 0.0));
    let orient = [("u0", 1.0), ("u1", 0.0), ("u2", 0.0), ("u3", 0.0)]
        .map(|(u, default)| value(&format!("base_frame_orient_{u}"), default));
    (pos, orient)
}

/// One `MECHANICAL_UNIT_GROUP` instance (RobotWare 6 writes them in SYS.cfg, a
/// MultiMove backup may have them in MOC.cfg).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Group {
    /// `-robot` ("ROB_1"); none for a group without a robot (the group of a positioner's
    /// task, which moves external units only).
    pub robot: Option<String>,
    pub line: u32,
}

/// The `MECHANICAL_UNIT_GROUP` named `name`, if the file has it.
pub fn group(file: &CfgFile, name: &str) -> Option<Group> {
    let found = named(file, "MECHANICAL_UNIT_GROUP", name)?;
    let robot = found.value("robot").filter(|r| !r.is_empty()).map(str::to_owned);
    Some(Group { robot, line: found.line })
}

/// The robot of the `MECHANICAL_UNIT_GROUP` named `group` (its `-robot`, "ROB_1"): `None`
/// when the file has no such group, `Some(None)` for a group without a robot.
pub fn group_robot(file: &CfgFile, group: &str) -> Option<Option<String>> {
    self::group(file, group).map(|g| g.robot)
}

/// The mechanical units of a MOC file that are not robots (`MECHANICAL_UNIT` instances
/// no `ROBOT` instance names): external axes, tracks, positioners.
pub fn external_units(file: &CfgFile) -> Vec<String> {
    let robots: Vec<String> = robots(file).into_iter().map(|r| r.name.to_ascii_uppercase()).collect();
    file.instances("MECHANICAL_UNIT")
        .filter_map(|inst| inst.name())
        .filter(|name| !robots.contains(&name.to_ascii_uppercase()))
        .map(str::to_owned)
        .collect()
}

/// One axis of an external mechanical unit as MOC.cfg links it together, its values as
/// written (SI units: metres or radians, seconds); `None` where a link or a value is
/// missing. `SINGLE` names the `SINGLE_TYPE` (its `-mechanics`) and the `JOINT` (its
/// `-logical_axis`), the joint its `ARM` (the working range; its `ACC_DATA`, the
/// acceleration), its `TRANSMISSION` (the gear ratio) and its `DRIVE_SYSTEM`, whose
/// `STRESS_DUTY_CYCLE` gives the motor's highest speed.
#[derive(Debug, Clone, PartialEq)]
pub struct SingleAxis {
    pub single: String,
    pub mechanics: Option<String>,
    pub logical_axis: Option<i64>,
    pub lower: Option<f64>,
    pub upper: Option<f64>,
    pub acc: Option<f64>,
    /// `-transm_joint`: motor radians per unit of the joint.
    pub transmission: Option<f64>,
    /// `-speed_absolute_max`: the motor's highest speed, rad/s.
    pub motor_speed_max: Option<f64>,
    /// The `SINGLE`'s base frame (as [`Robot::base_frame`]): where the axis stands in
    /// the world (a track moves along its x axis).
    pub base_frame: ([f64; 3], [f64; 4]),
}

/// An external mechanical unit (a `MECHANICAL_UNIT` no `ROBOT` is): its flags and its
/// axes (`-use_single_0` … `-use_single_5`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MechUnit {
    pub name: String,
    pub line: u32,
    pub active_at_start: bool,
    pub deactivation_forbidden: bool,
    /// A `ROBOT` has its base coordinated with this unit (`-base_frame_coordinated`):
    /// the unit carries that robot.
    pub carries_robot: bool,
    pub axes: Vec<SingleAxis>,
}

/// The external mechanical units of a MOC file with their axes.
pub fn mechanical_units(file: &CfgFile) -> Vec<MechUnit> {
    let external = external_units(file);
    file.instances("MECHANICAL_UNIT")
        .filter(|inst| inst.name().is_some_and(|n| external.iter().any(|e| e == n)))
        .map(|inst| {
            let name = inst.name().unwrap_or_default().to_owned();
            let carries_robot = file
                .instances("ROBOT")
                .any(|r| r.value("base_frame_coordinated").is_some_and(|u| u.eq_ignore_ascii_case(&name)));
            let axes = (0..6)
                .filter_map(|k| inst.value(&format!("use_single_{k}")))
                .map(|single| single_axis(file, single))
                .collect();
            MechUnit {
                line: inst.line,
                active_at_start: inst.has("activate_at_start_up"),
                deactivation_forbidden: inst.has("deactivation_forbidden"),
                carries_robot,
                axes,
                name,
            }
        })
        .collect()
}

/// The name of every mechanical unit of a MOC file, in configuration order: each
/// `MECHANICAL_UNIT` (robots, tracks, positioners, whatever their mechanics) and each
/// `ROBOT` (`ROB_1`, `ROB_L`); each is predefined `mecunit` data of the system.
pub fn unit_names(file: &CfgFile) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for inst in file.instances("MECHANICAL_UNIT").chain(file.instances("ROBOT")) {
        if let Some(name) = inst.name().filter(|n| !n.is_empty()) {
            if !names.iter().any(|known| known.eq_ignore_ascii_case(name)) {
                names.push(name.to_owned());
            }
        }
    }
    names
}

/// The instance of a type with this `-name`.
fn named<'a>(file: &'a CfgFile, type_name: &'a str, name: &str) -> Option<&'a crate::Instance> {
    file.instances(type_name).find(|inst| inst.name().is_some_and(|n| n.eq_ignore_ascii_case(name)))
}

/// A number attribute of the instance of a type with this `-name`.
fn number(file: &CfgFile, type_name: &str, name: Option<&str>, attr: &str) -> Option<f64> {
    parsed(named(file, type_name, name?)?, attr)
}

/// An attribute's value read as a number; `None` when absent or not one.
fn parsed<T: std::str::FromStr>(inst: &crate::Instance, attr: &str) -> Option<T> {
    inst.value(attr)?.trim().parse().ok()
}

fn single_axis(file: &CfgFile, single: &str) -> SingleAxis {
    let inst = named(file, "SINGLE", single);
    let link = |attr: &str| inst.and_then(|i| i.value(attr));
    let mechanics = link("use_single_type")
        .and_then(|t| named(file, "SINGLE_TYPE", t))
        .and_then(|t| t.value("mechanics"))
        .map(str::to_owned);
    let joint = link("use_joint").and_then(|j| named(file, "JOINT", j));
    let joint_link = |attr: &str| joint.and_then(|j| j.value(attr));
    let arm = joint_link("use_arm").and_then(|a| named(file, "ARM", a));
    let stress = joint_link("use_drive_system")
        .and_then(|d| named(file, "DRIVE_SYSTEM", d))
        .and_then(|d| d.value("use_stress_duty_cycle"));
    SingleAxis {
        single: single.to_owned(),
        mechanics,
        logical_axis: joint.and_then(|j| parsed(j, "logical_axis")),
        lower: arm.and_then(|a| parsed(a, "lower_joint_bound")),
        upper: arm.and_then(|a| parsed(a, "upper_joint_bound")),
        acc: number(file, "ACC_DATA", arm.and_then(|a| a.value("use_acc_data")), "wc_acc"),
        transmission: number(file, "TRANSMISSION", joint_link("use_transmission"), "transm_joint"),
        motor_speed_max: number(file, "STRESS_DUTY_CYCLE", stress, "speed_absolute_max"),
        base_frame: inst.map_or(([0.0; 3], [1.0, 0.0, 0.0, 0.0]), base_frame),
    }
}
