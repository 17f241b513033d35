//! `rapid.toml`, the project manifest for users without a controller backup: it
//! describes the system as a backup's SYS.cfg does (tasks, their type, entry routine,
//! foreground, TrustLevel, message queue), plus each task's module files, the I/O
//! configuration (an EIO.cfg-format file) and the controller's HOME: folder.
//!
//! Reading yields the same description a backup gives, a [`Sys`] and a list of files
//! per task, so `check` and `run` treat both alike. Every problem is a finding at its
//! place in the manifest (E0701). The TOML reader stops at the first structural
//! problem (TOML syntax, an unknown key, a value of the wrong TOML type); every other
//! problem is found and reported together. See docs/manifest.md.

use std::ops::Range;
use std::path::{Path, PathBuf};

use crate::TrustLevel;
use rapid_config::sys::{Rmq, RmqType, Sys, Task, TaskType};
use serde::Deserialize;
use toml::Spanned;

use super::glob;

/// The file name that makes a folder a project.
pub const FILE_NAME: &str = "rapid.toml";

/// At most 20 tasks (RAPID overview §1.20, multitasking).
const MAX_TASKS: usize = rapid_limits::TASKS;

/// The longest RAPID identifier.
const MAX_IDENT: usize = rapid_limits::IDENT_CHARS;

// uncertain: the ranges of ABB's system parameters manual (Controller, Task) as
// rapid-config reads them from SYS.cfg: at most 3000 bytes and 10 messages.
const RMQ_MAX_MSG_SIZE: i64 = 3000;
const RMQ_MAX_NO_OF_MSG: i64 = 10;

/// The manifest a PATH names: a `.toml` file, or a folder holding a `rapid.toml` that
/// describes a system. A folder's `rapid.toml` holding only tool settings (`[fmt]`, as
/// docs/fmt.md suggests for a folder of modules) describes none: the folder stays a
/// folder of modules.
pub fn manifest_path(path: &Path) -> Option<PathBuf> {
    if path.is_dir() {
        let file = path.join(FILE_NAME);
        return (file.is_file() && describes_system(&file)).then_some(file);
    }
    let ext = path.extension()?.to_str()?;
    ext.eq_ignore_ascii_case("toml").then(|| path.to_path_buf())
}

/// Whether a folder's `rapid.toml` has a table besides the tools' settings. A file
/// that cannot be read or parsed counts as a manifest, so reading it reports why.
fn describes_system(file: &Path) -> bool {
    const TOOL_TABLES: &[&str] = &["fmt"];
    let Ok(text) = std::fs::read_to_string(file) else { return true };
    match text.parse::<toml::Table>() {
        Ok(table) => table.keys().any(|key| !TOOL_TABLES.contains(&key.as_str())),
        Err(_) => true,
    }
}

/// A problem in the manifest: where (byte offsets into its text) and what.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Finding {
    pub span: Range<usize>,
    pub message: String,
}

/// What a manifest describes.
#[derive(Debug, Default)]
pub struct Manifest {
    /// The tasks with their attributes, as SYS.cfg's CAB_TASKS would give them.
    pub sys: Sys,
    /// For each task of [`Manifest::sys`], its module files in load order.
    pub modules: Vec<Vec<PathBuf>>,
    /// `[system] shared`: modules installed shared (SYS.cfg `CAB_TASK_MODULES -Shared`),
    /// one instance every task sees.
    pub shared: Vec<PathBuf>,
    /// The EIO.cfg-format file of the I/O configuration, and where the manifest names it.
    pub io: Option<(PathBuf, Range<usize>)>,
    /// The controller root: the folder whose `HOME` subfolder is the HOME: device.
    pub root: PathBuf,
    /// `[system] name`, and `robot`: the model the motion tasks move (`motion_out.rs`).
    pub name: Option<String>,
    pub robot: Option<String>,
    /// `[system] options`: the software options the system has (`rapid check` knows
    /// their names); `None` when not given.
    pub options: Option<Vec<String>>,
    /// `[[unit]]`: external mechanical units and the tasks they belong to.
    pub units: Vec<super::TaskUnit>,
    /// `[[conveyor]]`: conveyors for conveyor tracking and the tasks they belong to.
    pub conveyors: Vec<super::TaskConveyor>,
    /// A motion task's `base` and `orientation`: where its robot stands in the world (mm,
    /// a unit quaternion), by task name.
    pub robot_bases: Vec<(String, [f64; 3], [f64; 4])>,
    /// A motion task's own `robot`: its model's name, or `None` for a task that moves
    /// external units only (a positioner's), by task name.
    pub task_robots: Vec<(String, Option<String>)>,
    /// `[system] start_joints`: the axis values (degrees) the robots start at.
    pub start_joints: Option<[f64; 6]>,
    /// `[system] controller_ip`: the controller's own address in its cell, as
    /// `--controller-ip` gives it (the flag wins).
    pub controller_ip: Option<std::net::Ipv4Addr>,
    pub findings: Vec<Finding>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawManifest {
    system: Option<RawSystem>,
    #[serde(default)]
    task: Vec<Spanned<RawTask>>,
    #[serde(default)]
    unit: Vec<Spanned<super::manifest_units::RawUnit>>,
    #[serde(default)]
    conveyor: Vec<Spanned<super::manifest_units::RawConveyor>>,
    /// `[fmt]`: the formatter's options, read by `rapid fmt` (commands/fmt_config.rs).
    #[serde(default, rename = "fmt")]
    _fmt: Option<toml::Table>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSystem {
    name: Option<Spanned<String>>,
    robot: Option<Spanned<String>>,
    options: Option<Vec<String>>,
    io: Option<Spanned<String>>,
    home: Option<Spanned<String>>,
    shared: Option<Spanned<Vec<Spanned<String>>>>,
    start_joints: Option<Spanned<Vec<f64>>>,
    controller_ip: Option<Spanned<String>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTask {
    name: Spanned<String>,
    #[serde(rename = "type")]
    task_type: Option<Spanned<String>>,
    entry: Option<Spanned<String>>,
    modules: Spanned<Vec<Spanned<String>>>,
    motion: Option<bool>,
    foreground: Option<Spanned<String>>,
    trust_level: Option<Spanned<String>>,
    rmq: Option<RawRmq>,
    base: Option<Spanned<Vec<f64>>>,
    orientation: Option<Spanned<Vec<f64>>>,
    /// A model's name, or whether the task moves a robot at all (`false`).
    robot: Option<Spanned<toml::Value>>,
    /// SYS.cfg's `-UseMechanicalUnitGroup`: a task that is no motion task reads the robot
    /// of the motion task with this group (`rob1` is the first motion task's).
    mechanical_unit_group: Option<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRmq {
    #[serde(rename = "type")]
    rmq_type: Option<Spanned<String>>,
    mode: Option<Spanned<String>>,
    max_msg_size: Option<Spanned<i64>>,
    max_no_of_msg: Option<Spanned<i64>>,
}

/// The side a name says (`T_ROB_L`: left; `T_ROB_R`, `right_arm`: right), by its
/// parts between `_`, `-` and spaces.
fn side_of(name: &str) -> Option<rapid_motion::kinematics::yumi::Side> {
    use rapid_motion::kinematics::yumi::Side;
    name.to_ascii_lowercase().split(['_', '-', ' ']).find_map(|part| match part {
        "l" | "left" => Some(Side::Left),
        "r" | "right" => Some(Side::Right),
        _ => None,
    })
}

/// Reads the manifest `text` of the file at `path`.
pub fn read(path: &Path, text: &str) -> Manifest {
    let dir = path.parent().map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let mut reader = Reader { dir, text, manifest: Manifest::default() };
    reader.manifest.root = reader.dir.clone();
    match toml::from_str::<RawManifest>(text) {
        Ok(raw) => reader.read(raw),
        Err(err) => {
            let span = err.span().unwrap_or(0..0);
            reader.find(span, err.message().trim_end().to_owned());
        }
    }
    // In the order of the text, which is how `check` and `run` show them.
    reader.manifest.findings.sort_by_key(|finding| finding.span.start);
    reader.manifest
}

struct Reader<'a> {
    /// The manifest's folder: relative paths start here.
    dir: PathBuf,
    text: &'a str,
    manifest: Manifest,
}

impl Reader<'_> {
    fn find(&mut self, span: Range<usize>, message: impl Into<String>) {
        self.manifest.findings.push(Finding { span, message: message.into() });
    }

    fn read(&mut self, raw: RawManifest) {
        if let Some(system) = raw.system {
            self.system(system);
        }
        if raw.task.is_empty() {
            self.find(0..0, "the manifest configures no task: add a `[[task]]` table with its `name` and `modules`");
            return;
        }
        if raw.task.len() > MAX_TASKS {
            let extra = raw.task.len() - MAX_TASKS;
            let span = raw.task[MAX_TASKS].span();
            self.find(span, format!("at most {MAX_TASKS} tasks; {extra} more are configured"));
        }
        for (idx, task) in raw.task.iter().enumerate() {
            let line = line_of(self.text, task.span().start);
            self.task(idx, task.get_ref(), line);
        }
        self.foregrounds(&raw.task);
        self.units(&raw.unit);
        self.conveyors(&raw.conveyor);
        self.yumi_arms_by_task();
    }

    /// `[system] robot` an IRB 14000 YuMi, whose name alone gives the right arm (ROB_R,
    /// the system's first robot): a motion task without a `robot` of its own whose name
    /// says a side (`T_ROB_L`, `T_ROB_R`, as a YuMi system names its tasks) moves that
    /// side's arm, as MOC.cfg's arm names `ROB_L`/`ROB_R` choose it in a backup.
    fn yumi_arms_by_task(&mut self) {
        let system = self.manifest.robot.as_deref().and_then(rapid_motion::find_model);
        if system.is_none_or(|model| model.yumi.is_none()) {
            return;
        }
        for task in self.manifest.sys.tasks.iter().filter(|t| t.motion_task) {
            if self.manifest.task_robots.iter().any(|(t, _)| t.eq_ignore_ascii_case(&task.name)) {
                continue;
            }
            let Some(side) = side_of(&task.name) else { continue };
            if let Some(arm) = rapid_motion::robots::yumi_arms().iter().find(|arm| arm.yumi == Some(side)) {
                self.manifest.task_robots.push((task.name.clone(), Some(arm.name.to_owned())));
            }
        }
    }

    /// `[[conveyor]]`: each conveyor's task must be a motion task of the manifest.
    fn conveyors(&mut self, raw: &[Spanned<super::manifest_units::RawConveyor>]) {
        let mut found = Vec::new();
        let taken: Vec<String> = self.manifest.units.iter().map(|u| u.unit.name.clone()).collect();
        let conveyors = super::manifest_units::read_conveyors(raw, &taken, &mut |span, message| {
            found.push(Finding { span, message })
        });
        for (conveyor, spanned) in conveyors.iter().zip(raw) {
            found.extend(self.no_motion_task("conveyor", &conveyor.name, conveyor.task.as_deref(), spanned.span()));
        }
        self.manifest.findings.extend(found);
        self.manifest.conveyors = conveyors;
    }

    /// `[[unit]]`: each unit's task must be a motion task of the manifest.
    fn units(&mut self, raw: &[Spanned<super::manifest_units::RawUnit>]) {
        let mut found = Vec::new();
        let units = super::manifest_units::read(raw, &mut |span, message| found.push(Finding { span, message }));
        for (unit, spanned) in units.iter().zip(raw) {
            found.extend(self.no_motion_task("unit", &unit.unit.name, unit.task.as_deref(), spanned.span()));
        }
        self.manifest.findings.extend(found);
        self.manifest.units = units;
    }

    /// A finding when the `task` a unit or conveyor names is no motion task here.
    fn no_motion_task(&self, what: &str, name: &str, task: Option<&str>, span: Range<usize>) -> Option<Finding> {
        let task = task?;
        let motion = self.manifest.sys.tasks.iter().any(|t| t.name.eq_ignore_ascii_case(task) && t.motion_task);
        let message = format!("{what} `{name}`: `{task}` is no motion task of this manifest");
        (!motion).then_some(Finding { span, message })
    }

    fn system(&mut self, system: RawSystem) {
        if let Some(name) = system.name {
            self.non_empty(&name, "name");
            self.manifest.name = Some(name.into_inner());
        }
        if let Some(robot) = system.robot {
            self.non_empty(&robot, "robot");
            self.manifest.robot = Some(robot.into_inner());
        }
        if let Some(joints) = system.start_joints {
            match <[f64; 6]>::try_from(joints.get_ref().as_slice()) {
                Ok(values) if values.iter().all(|q| q.is_finite()) => self.manifest.start_joints = Some(values),
                _ => self.find(joints.span(), "`start_joints` is six axis values in degrees, e.g. [0, 0, 0, 0, 30, 0]"),
            }
        }
        if let Some(ip) = system.controller_ip {
            self.controller_ip(&ip);
        }
        self.manifest.options = system.options;
        if let Some(io) = system.io {
            let path = self.dir.join(io.get_ref());
            if io.get_ref().trim().is_empty() {
                self.find(io.span(), "`io` is empty: name the EIO.cfg-format file of the I/O configuration");
            } else if !path.is_file() {
                self.find(io.span(), format!("no I/O configuration file `{}`", path.display()));
            } else {
                self.manifest.io = Some((path, io.span()));
            }
        }
        if let Some(home) = system.home {
            self.home(&home);
        }
        if let Some(shared) = system.shared {
            self.manifest.shared = self.modules("the shared modules", &shared);
        }
    }

    /// `controller_ip`: an IPv4 address in dotted form, as `--controller-ip` takes it.
    fn controller_ip(&mut self, ip: &Spanned<String>) {
        match ip.get_ref().trim().parse::<std::net::Ipv4Addr>() {
            Ok(addr) => self.manifest.controller_ip = Some(addr),
            Err(_) => {
                let message =
                    format!("`controller_ip` `{}` is not an IPv4 address such as 192.168.125.1", ip.get_ref());
                self.find(ip.span(), message);
            }
        }
    }

    fn non_empty(&mut self, value: &Spanned<String>, key: &str) {
        if value.get_ref().trim().is_empty() {
            self.find(value.span(), format!("`{key}` is empty"));
        }
    }

    /// `home`: the HOME: folder. The file devices are the subfolders `HOME`, `TEMP`,
    /// `RAMDISK` and `BACKUP` of one controller folder (spelt so), so the folder must
    /// be named HOME and its parent becomes the controller root.
    fn home(&mut self, home: &Spanned<String>) {
        let path = self.dir.join(home.get_ref());
        let named_home = path.file_name().and_then(|n| n.to_str()) == Some("HOME");
        if !named_home {
            let message = format!(
                "the HOME: folder `{}` must be named HOME: the file devices HOME:, TEMP:, RAMDISK: and \
                 BACKUP: are the folders HOME, TEMP, RAMDISK and BACKUP side by side",
                path.display()
            );
            self.find(home.span(), message);
            return;
        }
        if path.exists() && !path.is_dir() {
            self.find(home.span(), format!("`{}` is not a folder", path.display()));
            return;
        }
        self.manifest.root = path.parent().map_or_else(|| self.dir.clone(), Path::to_path_buf);
    }

    fn task(&mut self, idx: usize, raw: &RawTask, line: u32) {
        let name = raw.name.get_ref().clone();
        if let Some(why) = identifier_problem(&name) {
            self.find(raw.name.span(), format!("task name `{name}` {why}"));
        }
        if self.manifest.sys.task(&name).is_some() {
            self.find(raw.name.span(), format!("task `{name}` is configured twice"));
        }
        // The first task is the robot's program (T_ROB1 on a real system): NORMAL and
        // the motion task. Further tasks default as SYS.cfg's tasks without -Type do.
        let task_type = match &raw.task_type {
            None if idx == 0 => TaskType::Normal,
            None => TaskType::SemiStatic,
            Some(text) => task_type(text.get_ref()).unwrap_or_else(|| {
                let message =
                    format!("task `{name}`: unknown type `{}` (NORMAL, STATIC or SEMISTATIC)", text.get_ref());
                self.find(text.span(), message);
                TaskType::Normal
            }),
        };
        let entry = match &raw.entry {
            None => "main".to_owned(),
            Some(entry) => {
                if let Some(why) = identifier_problem(entry.get_ref()) {
                    self.find(entry.span(), format!("task `{name}`: entry routine `{}` {why}", entry.get_ref()));
                }
                entry.get_ref().clone()
            }
        };
        let trust_level = raw.trust_level.as_ref().map(|level| {
            if TrustLevel::parse(level.get_ref()).is_none() {
                let message = format!(
                    "task `{name}`: unknown trust_level `{}` (SysFail, SysHalt, SysStop or NoSafety)",
                    level.get_ref()
                );
                self.find(level.span(), message);
            }
            level.get_ref().clone()
        });
        let rmq = raw.rmq.as_ref().map_or_else(Rmq::default, |rmq| self.rmq(&name, rmq));
        let modules = self.modules(&name, &raw.modules);
        let motion_task = raw.motion.unwrap_or(idx == 0);
        self.robot_base(&name, raw, motion_task);
        self.task_robot(&name, raw, motion_task);
        self.manifest.sys.tasks.push(Task {
            name,
            task_type,
            entry,
            entry_span: raw.entry.as_ref().map(Spanned::span),
            trust_level,
            motion_task,
            mechanical_unit_group: raw.mechanical_unit_group.clone(),
            hidden: false,
            foreground: raw.foreground.as_ref().map(|f| f.get_ref().clone()).filter(|f| !f.is_empty()),
            rmq,
            line,
        });
        self.manifest.modules.push(modules);
    }

    /// A motion task's `base`/`orientation`: where its robot stands in the world.
    fn robot_base(&mut self, task: &str, raw: &RawTask, motion_task: bool) {
        let Some(key) = raw.base.as_ref().or(raw.orientation.as_ref()) else { return };
        if !motion_task {
            let message = format!("task `{task}`: base and orientation place a motion task's robot (motion = true)");
            self.find(key.span(), message);
            return;
        }
        let mut found = Vec::new();
        let mut find = |span: Range<usize>, message: String| found.push(Finding { span, message });
        let base = super::manifest_units::fixed::<3>(raw.base.as_ref(), [0.0; 3], "base", task, &mut find);
        let orientation = super::manifest_units::orientation(raw.orientation.as_ref(), task, &mut find);
        self.manifest.findings.extend(found);
        self.manifest.robot_bases.push((task.to_owned(), base, orientation));
    }

    /// A motion task's own `robot`: a model (known to us), `true` (the system's), or
    /// `false` (none: the task moves its external units only).
    fn task_robot(&mut self, task: &str, raw: &RawTask, motion_task: bool) {
        let Some(robot) = &raw.robot else { return };
        if !motion_task {
            let message = format!("task `{task}`: robot is a motion task's (motion = true)");
            self.find(robot.span(), message);
            return;
        }
        let chosen = match robot.get_ref() {
            toml::Value::Boolean(true) => return,
            toml::Value::Boolean(false) => None,
            toml::Value::String(name) => {
                if rapid_motion::find_model(name).is_none() {
                    let known: Vec<&str> = rapid_motion::robots::all_models().map(|m| m.name).collect();
                    let message = format!("task `{task}`: unknown robot model `{name}` (known: {})", known.join(", "));
                    self.find(robot.span(), message);
                }
                Some(name.clone())
            }
            _ => {
                let message =
                    format!("task `{task}`: robot is a robot model's name, or false for a task that moves none");
                self.find(robot.span(), message);
                return;
            }
        };
        self.manifest.task_robots.push((task.to_owned(), chosen));
    }

    fn rmq(&mut self, task: &str, raw: &RawRmq) -> Rmq {
        let mut rmq = Rmq::default();
        if let Some(text) = &raw.rmq_type {
            match text.get_ref().to_ascii_lowercase().as_str() {
                "none" => rmq.rmq_type = RmqType::None,
                "internal" => rmq.rmq_type = RmqType::Internal,
                "remote" => rmq.rmq_type = RmqType::Remote,
                _ => self.find(
                    text.span(),
                    format!("task `{task}`: unknown rmq type `{}` (None, Internal or Remote)", text.get_ref()),
                ),
            }
        }
        if let Some(text) = &raw.mode {
            match text.get_ref().to_ascii_lowercase().as_str() {
                "interrupt" => rmq.synchronous = false,
                "synchronous" => rmq.synchronous = true,
                _ => self.find(
                    text.span(),
                    format!("task `{task}`: unknown rmq mode `{}` (Interrupt or Synchronous)", text.get_ref()),
                ),
            }
        }
        if let Some(size) = &raw.max_msg_size {
            rmq.max_msg_size = self.bounded(task, "max_msg_size", size, RMQ_MAX_MSG_SIZE).unwrap_or(rmq.max_msg_size);
        }
        if let Some(count) = &raw.max_no_of_msg {
            rmq.max_no_of_msg =
                self.bounded(task, "max_no_of_msg", count, RMQ_MAX_NO_OF_MSG).unwrap_or(rmq.max_no_of_msg);
        }
        rmq
    }

    fn bounded(&mut self, task: &str, key: &str, value: &Spanned<i64>, max: i64) -> Option<u32> {
        let n = *value.get_ref();
        if (1..=max).contains(&n) {
            return u32::try_from(n).ok();
        }
        self.find(value.span(), format!("task `{task}`: rmq {key} {n} is not a number from 1 to {max}"));
        None
    }

    /// The files of a task's `modules` list (or of `[system] shared`, when `task` is
    /// "the shared modules"), each entry a file, a folder (its module files, sorted) or
    /// a pattern.
    fn modules(&mut self, task: &str, list: &Spanned<Vec<Spanned<String>>>) -> Vec<PathBuf> {
        if list.get_ref().is_empty() {
            self.find(list.span(), format!("{owner} has no modules", owner = owner_name(task)));
        }
        let mut files = Vec::new();
        for entry in list.get_ref() {
            let text = entry.get_ref();
            if text.trim().is_empty() {
                self.find(entry.span(), "an empty module path");
                continue;
            }
            if glob::is_pattern(text) {
                self.pattern(entry, &mut files);
                continue;
            }
            let path = self.dir.join(text);
            if path.is_dir() {
                let found = folder_modules(&path);
                if found.is_empty() {
                    let message = format!(
                        "folder `{}` holds no RAPID module files ({})",
                        path.display(),
                        super::extension_list()
                    );
                    self.find(entry.span(), message);
                }
                files.extend(found);
            } else if !path.exists() {
                self.find(entry.span(), format!("no module file `{}`", path.display()));
            } else if !is_module(&path) {
                self.find(entry.span(), not_a_module(&path));
            } else {
                files.push(path);
            }
        }
        files
    }

    fn pattern(&mut self, entry: &Spanned<String>, files: &mut Vec<PathBuf>) {
        let matched = glob::files(&self.dir, entry.get_ref());
        if matched.is_empty() {
            self.find(entry.span(), format!("`{}` matches no file", entry.get_ref()));
        }
        for path in matched {
            if is_module(&path) {
                files.push(path);
            } else {
                let message = format!(
                    "`{}`, matched by this pattern, is not a RAPID module file ({})",
                    path.display(),
                    super::extension_list()
                );
                self.find(entry.span(), message);
            }
        }
    }

    /// A `foreground` must name another task of the manifest, not in a cycle.
    fn foregrounds(&mut self, tasks: &[Spanned<RawTask>]) {
        for task in tasks {
            let task = task.get_ref();
            let Some(foreground) = &task.foreground else { continue };
            let (name, target) = (task.name.get_ref(), foreground.get_ref());
            if let Some(message) = rapid_config::sys::foreground_finding(&self.manifest.sys, name, target) {
                self.find(foreground.span(), message);
            }
        }
    }
}

/// How a module list's owner is named in a finding: `task T_ROB1`, or the shared list.
fn owner_name(task: &str) -> String {
    if task == "the shared modules" {
        "`shared`".to_owned()
    } else {
        format!("task `{task}`")
    }
}

fn task_type(text: &str) -> Option<TaskType> {
    Some(match text.to_ascii_uppercase().as_str() {
        "NORMAL" => TaskType::Normal,
        "STATIC" => TaskType::Static,
        "SEMISTATIC" => TaskType::SemiStatic,
        _ => return None,
    })
}

/// Why `name` cannot be a RAPID identifier (task names become `<name>Id` taskid data).
pub(super) fn identifier_problem(name: &str) -> Option<&'static str> {
    let mut chars = name.chars();
    match chars.next() {
        None => return Some("is empty"),
        Some(c) if !c.is_ascii_alphabetic() => return Some("does not start with a letter"),
        Some(_) => {}
    }
    if !chars.all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Some("is not a RAPID name (letters, digits and _)");
    }
    (name.len() > MAX_IDENT).then_some("is longer than 32 characters")
}

fn is_module(path: &Path) -> bool {
    path.is_file() && super::file_kind(path) == Some(super::FileKind::Module)
}

fn not_a_module(path: &Path) -> String {
    format!("`{}` is not a RAPID module file ({})", path.display(), super::extension_list())
}

/// The module files of a folder (not of its subfolders), sorted by name.
fn folder_modules(folder: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(folder) else { return Vec::new() };
    let mut files: Vec<PathBuf> = entries.filter_map(Result::ok).map(|e| e.path()).filter(|p| is_module(p)).collect();
    files.sort();
    files
}

/// The 1-based line of a byte offset.
fn line_of(text: &str, offset: usize) -> u32 {
    let offset = offset.min(text.len());
    let line = text.as_bytes()[..offset].iter().filter(|&&b| b == b'\n').count() + 1;
    u32::try_from(line).unwrap_or(u32::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn project(name: &str, toml: &str) -> (PathBuf, Manifest) {
        let dir = std::env::temp_dir().join(format!("rapid-manifest-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("src")).unwrap();
        std::fs::write(dir.join("src/A.mod"), "MODULE A\nENDMODULE\n").unwrap();
        std::fs::write(dir.join("src/B.sys"), "MODULE B(SYSMODULE)\nENDMODULE\n").unwrap();
        let path = dir.join(FILE_NAME);
        std::fs::write(&path, toml).unwrap();
        let manifest = read(&path, toml);
        (dir, manifest)
    }

    #[test]
    fn defaults_follow_the_first_task() {
        let toml = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"src\"]\n\n\
                    [[task]]\nname = \"T_BACK\"\nmodules = [\"src/*.sys\", \"src/A.mod\"]\n";
        let (dir, manifest) = project("defaults", toml);
        assert_eq!(manifest.findings, []);
        let [first, second] = &manifest.sys.tasks[..] else { panic!("two tasks") };
        assert_eq!((first.task_type, first.motion_task, first.entry.as_str()), (TaskType::Normal, true, "main"));
        assert_eq!((second.task_type, second.motion_task), (TaskType::SemiStatic, false));
        assert_eq!((first.line, second.line), (1, 5));
        assert_eq!(second.rmq, Rmq::default());
        assert_eq!(manifest.modules[0], [dir.join("src/A.mod"), dir.join("src/B.sys")]);
        assert_eq!(manifest.modules[1], [dir.join("src/B.sys"), dir.join("src/A.mod")]);
        assert_eq!(manifest.root, dir);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn every_key_is_read() {
        let toml = "[system]\nname = \"cell\"\nrobot = \"IRB120-3/0.58\"\nhome = \"run/HOME\"\n\n\
                    [[task]]\nname = \"T_MAIN\"\ntype = \"static\"\nentry = \"go\"\nmodules = [\"src/A.mod\"]\n\
                    motion = false\ntrust_level = \"SysHalt\"\n\
                    rmq = { type = \"Remote\", mode = \"Synchronous\", max_msg_size = 3000, max_no_of_msg = 10 }\n\n\
                    [[task]]\nname = \"T_BG\"\nmodules = [\"src/B.sys\"]\nforeground = \"T_MAIN\"\n";
        let (dir, manifest) = project("keys", toml);
        assert_eq!(manifest.findings, []);
        assert_eq!((manifest.name.as_deref(), manifest.robot.as_deref()), (Some("cell"), Some("IRB120-3/0.58")));
        assert_eq!(manifest.root, dir.join("run"));
        let task = &manifest.sys.tasks[0];
        assert_eq!((task.task_type, task.entry.as_str(), task.motion_task), (TaskType::Static, "go", false));
        assert_eq!(task.trust_level.as_deref(), Some("SysHalt"));
        let rmq = Rmq { rmq_type: RmqType::Remote, synchronous: true, max_msg_size: 3000, max_no_of_msg: 10 };
        assert_eq!(task.rmq, rmq);
        assert_eq!(manifest.sys.tasks[1].foreground.as_deref(), Some("T_MAIN"));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_yumi_systems_tasks_move_the_arm_their_names_say() {
        use rapid_motion::kinematics::yumi::Side;
        // T_ROB_L gives no robot of its own: the left arm. T_ROB_R the right; a motion
        // task's own robot stands; T_ROB1 says no side and keeps the system's model.
        let toml = "[system]\nrobot = \"IRB 14000\"\n\n\
                    [[task]]\nname = \"T_ROB_L\"\nmodules = [\"src/A.mod\"]\nmotion = true\n\n\
                    [[task]]\nname = \"T_ROB_R\"\ntype = \"NORMAL\"\nmodules = [\"src/A.mod\"]\nmotion = true\n\n\
                    [[task]]\nname = \"T_ROB1\"\ntype = \"NORMAL\"\nmodules = [\"src/A.mod\"]\nmotion = true\n";
        let (dir, manifest) = project("yumi", toml);
        assert_eq!(manifest.findings, []);
        let side = |task: &str| {
            let chosen = manifest.task_robots.iter().find(|(t, _)| t == task).and_then(|(_, m)| m.as_deref());
            chosen.and_then(rapid_motion::find_model).and_then(|m| m.yumi)
        };
        assert_eq!((side("T_ROB_L"), side("T_ROB_R"), side("T_ROB1")), (Some(Side::Left), Some(Side::Right), None));
        // A task's own robot wins: here both arms are the right one.
        let own = toml.replacen("motion = true\n", "motion = true\nrobot = \"ROB_R_14000_05_05\"\n", 1);
        let (dir2, manifest) = project("yumi_own", &own);
        let chosen: Vec<_> = manifest.task_robots.iter().filter(|(t, _)| t == "T_ROB_L").collect();
        assert_eq!(chosen.len(), 1);
        let model = chosen[0].1.as_deref().and_then(rapid_motion::find_model).and_then(|m| m.yumi);
        assert_eq!(model, Some(Side::Right));
        let _ = std::fs::remove_dir_all(&dir);
        let _ = std::fs::remove_dir_all(&dir2);
    }

    #[test]
    fn names_must_be_rapid_names() {
        assert_eq!(identifier_problem("T_ROB1"), None);
        assert_eq!(identifier_problem(""), Some("is empty"));
        assert_eq!(identifier_problem("_x"), Some("does not start with a letter"));
        assert_eq!(identifier_problem("T-1"), Some("is not a RAPID name (letters, digits and _)"));
        assert_eq!(identifier_problem(&"a".repeat(33)), Some("is longer than 32 characters"));
        let (dir, manifest) = project("self", "[[task]]\nname = \"T\"\nmodules = [\"src\"]\nforeground = \"t\"\n");
        assert_eq!(manifest.findings.len(), 1);
        assert_eq!(manifest.findings[0].message, "task `T` cannot run in its own background");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
