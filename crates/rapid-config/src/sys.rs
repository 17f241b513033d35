//! The controller configuration (`SYS.cfg`): RAPID tasks (`CAB_TASKS`) and the modules
//! loaded into them (`CAB_TASK_MODULES`).

use crate::{CfgError, CfgFile, Instance};

/// `-Type` of a task.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TaskType {
    /// Started and stopped with the program.
    Normal,
    /// Started at power on; restarts from its start on a restart.
    Static,
    /// Started at power on; restarts from where it was.
    SemiStatic,
}

impl TaskType {
    fn parse(text: &str) -> Option<TaskType> {
        Some(match text.to_ascii_uppercase().as_str() {
            "NORMAL" => TaskType::Normal,
            "STATIC" => TaskType::Static,
            "SEMISTATIC" => TaskType::SemiStatic,
            _ => return None,
        })
    }
}

/// One `CAB_TASKS` instance.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Task {
    pub name: String,
    pub task_type: TaskType,
    /// `-Entry`, the routine the task starts in (`main` when not written).
    pub entry: String,
    /// `-TrustLevel` (`SysFail`, `SysHalt`, `SysStop`, `NoSafety`), when written.
    pub trust_level: Option<String>,
    /// `-MotionTask`: the task that moves the robot.
    pub motion_task: bool,
    /// `-UseMechanicalUnitGroup`, when written.
    pub mechanical_unit_group: Option<String>,
    /// `-Hidden`: not shown on the pendant.
    pub hidden: bool,
    /// `-TaskInForeground`: the task this one is in the background of (it runs only
    /// while that task idles); none for a task at the top level.
    pub foreground: Option<String>,
    pub line: u32,
}

/// One `CAB_TASK_MODULES` instance: a module file loaded into a task at start.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TaskModule {
    /// `-File`, e.g. `HOME:/user.sys`.
    pub file: String,
    pub module: Option<String>,
    /// `-Task`, or none with `-AllTask`.
    pub task: Option<String>,
    pub all_tasks: bool,
    /// `-Shared`: one instance visible in every task.
    pub shared: bool,
    pub line: u32,
}

/// The typed view of a SYS configuration.
#[derive(Debug, Clone, Default)]
pub struct Sys {
    pub tasks: Vec<Task>,
    pub modules: Vec<TaskModule>,
    pub errors: Vec<CfgError>,
}

impl Sys {
    /// The task of a name, ignoring case.
    pub fn task(&self, name: &str) -> Option<&Task> {
        self.tasks.iter().find(|t| t.name.eq_ignore_ascii_case(name))
    }
}

/// At most 20 tasks (RAPID overview, multitasking).
const MAX_TASKS: usize = 20;

/// Reads the tasks and task modules of a SYS file.
pub fn read(file: &CfgFile) -> Sys {
    let mut sys = Sys::default();
    for inst in file.instances("CAB_TASKS") {
        if let Some(task) = task(file, inst, &mut sys.errors) {
            if sys.task(&task.name).is_some() {
                error(file, &mut sys.errors, inst, format!("task `{}` is configured twice", task.name));
                continue;
            }
            sys.tasks.push(task);
        }
    }
    if sys.tasks.len() > MAX_TASKS {
        let extra = sys.tasks.len() - MAX_TASKS;
        if let Some(inst) = file.instances("CAB_TASKS").nth(MAX_TASKS) {
            error(file, &mut sys.errors, inst, format!("at most {MAX_TASKS} tasks; {extra} more are configured"));
        }
    }
    for inst in file.instances("CAB_TASKS") {
        let (Some(name), Some(value)) = (inst.name(), inst.attr("TaskInForeground").and_then(|a| a.value.as_ref()))
        else {
            continue;
        };
        if !value.text.is_empty() && sys.task(&value.text).is_none() {
            let message = format!("task `{name}` runs in the background of `{}`, which is not a task", value.text);
            sys.errors.push(CfgError { line: file.line_of(value.span.start), span: value.span.clone(), message });
        }
    }
    for inst in file.instances("CAB_TASK_MODULES") {
        let Some(path) = inst.value("File") else {
            error(file, &mut sys.errors, inst, "a task module without `-File`".to_owned());
            continue;
        };
        sys.modules.push(TaskModule {
            file: path.to_owned(),
            module: inst.value("ModName").map(str::to_owned),
            task: inst.value("Task").map(str::to_owned),
            all_tasks: inst.has("AllTask"),
            shared: inst.has("Shared"),
            line: inst.line,
        });
    }
    sys
}

fn error(file: &CfgFile, errors: &mut Vec<CfgError>, inst: &Instance, message: String) {
    let span = inst.attr("Name").map_or(inst.span.clone(), |a| a.name_span.clone());
    errors.push(CfgError { line: file.line_of(span.start), span, message });
}

fn task(file: &CfgFile, inst: &Instance, errors: &mut Vec<CfgError>) -> Option<Task> {
    let Some(name) = inst.name() else {
        error(file, errors, inst, "a task without `-Name`".to_owned());
        return None;
    };
    // uncertain: a task without `-Type` is SEMISTATIC, the default we believe the
    // system parameters manual gives (RobotWare writes `-Type` only when it differs).
    let task_type = match inst.value("Type") {
        None => TaskType::SemiStatic,
        Some(text) => match TaskType::parse(text) {
            Some(ty) => ty,
            None => {
                let message = format!("task `{name}`: unknown type `{text}` (NORMAL, STATIC or SEMISTATIC)");
                error(file, errors, inst, message);
                TaskType::SemiStatic
            }
        },
    };
    Some(Task {
        name: name.to_owned(),
        task_type,
        entry: inst.value("Entry").unwrap_or("main").to_owned(),
        trust_level: inst.value("TrustLevel").map(str::to_owned),
        motion_task: inst.has("MotionTask"),
        mechanical_unit_group: inst.value("UseMechanicalUnitGroup").map(str::to_owned),
        hidden: inst.has("Hidden"),
        foreground: inst.value("TaskInForeground").filter(|t| !t.is_empty()).map(str::to_owned),
        line: inst.line,
    })
}
