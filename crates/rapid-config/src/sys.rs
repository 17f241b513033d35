//! The controller configuration (`SYS.cfg`): RAPID tasks (`CAB_TASKS`) and the modules
//! loaded into them (`CAB_TASK_MODULES`).

use std::ops::Range;

use crate::{Attr, CfgError, CfgFile, Instance};

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
    /// Where the entry routine is written (its value's bytes in the file the task was
    /// read from); none when it is `main` by default.
    pub entry_span: Option<Range<usize>>,
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
    /// The task's RAPID Message Queue (`-RmqType`, `-RmqMode`, `-RmqMaxMsgSize`,
    /// `-RmqMaxNoOfMsg`).
    pub rmq: Rmq,
    pub line: u32,
}

/// `-RmqType`: who may send to the task's message queue.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RmqType {
    /// The task has no queue.
    None,
    /// Other tasks of the controller may send.
    Internal,
    /// Other tasks and clients outside the controller may send.
    Remote,
}

/// A task's RAPID Message Queue configuration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rmq {
    pub rmq_type: RmqType,
    /// `-RmqMode Synchronous` (RMQReadWait receives); else Interrupt (IRMQMessage traps).
    pub synchronous: bool,
    /// `-RmqMaxMsgSize`, bytes of data in one message.
    pub max_msg_size: u32,
    /// `-RmqMaxNoOfMsg`, messages the queue holds.
    pub max_no_of_msg: u32,
}

// uncertain: the defaults and ranges as we know them from ABB's system parameters
// manual (Controller, Task): no queue, interrupt mode, 400 bytes (max 3000), 5
// messages (max 10).
impl Default for Rmq {
    fn default() -> Self {
        Rmq { rmq_type: RmqType::None, synchronous: false, max_msg_size: 400, max_no_of_msg: 5 }
    }
}

const RMQ_MAX_MSG_SIZE: u32 = 3000;
const RMQ_MAX_NO_OF_MSG: u32 = 10;

/// One `CAB_TASK_MODULES` instance: a module file loaded into a task at start.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TaskModule {
    /// `-File`, e.g. `HOME:/user.sys`.
    pub file: String,
    pub module: Option<String>,
    /// The tasks `-Task` names (once per task: `-Task "T_ROB1" -Task "T_ROB2"` loads
    /// the module into both); none with `-AllTask`.
    pub tasks: Vec<String>,
    pub all_tasks: bool,
    /// `-Shared`: one instance visible in every task.
    pub shared: bool,
    pub line: u32,
}

/// One `CAB_EXEC_HOOKS` instance: an event routine (`-Routine`) run when the system
/// event `-Shelf` (POWER_ON, START, STOP, QSTOP, RESTART, RESET, STEP) happens, in
/// `-Task` or in every task (`-AllTask`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExecHook {
    pub routine: String,
    /// The `-Routine` value's bytes in the file.
    pub routine_span: Range<usize>,
    pub shelf: String,
    pub task: Option<String>,
    pub all_tasks: bool,
    /// `-AllMotionTask`: the routine runs in every motion task too.
    pub all_motion_tasks: bool,
    pub line: u32,
}

/// The system events an event routine may be hooked to.
pub const SHELVES: &[&str] = &["POWER_ON", "START", "STOP", "QSTOP", "RESTART", "RESET", "STEP"];

/// The typed view of a SYS configuration.
#[derive(Debug, Clone, Default)]
pub struct Sys {
    pub tasks: Vec<Task>,
    pub modules: Vec<TaskModule>,
    pub hooks: Vec<ExecHook>,
    pub errors: Vec<CfgError>,
    /// What RobotWare accepts but means nothing to us, at its line (a task naming
    /// itself as its foreground task).
    pub warnings: Vec<CfgError>,
}

impl Sys {
    /// The task of a name, ignoring case.
    pub fn task(&self, name: &str) -> Option<&Task> {
        self.tasks.iter().find(|t| t.name.eq_ignore_ascii_case(name))
    }
}

/// At most 20 tasks (RAPID overview, multitasking).
const MAX_TASKS: usize = rapid_limits::TASKS;

/// Reads the tasks and task modules of a SYS file.
pub fn read(file: &CfgFile) -> Sys {
    let mut sys = Sys::default();
    // Names seen, lower-cased: finding a duplicate must not be a scan per task.
    let mut names = std::collections::HashSet::new();
    for inst in file.instances("CAB_TASKS") {
        if let Some(task) = task(file, inst, &mut sys.errors) {
            if !names.insert(task.name.to_ascii_lowercase()) {
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
    // The system-wide limit first: over it the system is refused, and the foreground
    // chains of a thousand tasks are not followed (each check walks the chain).
    let tasks = if sys.tasks.len() > MAX_TASKS { 0 } else { usize::MAX };
    for inst in file.instances("CAB_TASKS").take(tasks) {
        let (Some(name), Some(value)) = (inst.name(), foreground_attr(inst).and_then(|a| a.value.as_ref())) else {
            continue;
        };
        let at = |message| CfgError { line: file.line_of(value.span.start), span: value.span.clone(), message };
        if value.text.eq_ignore_ascii_case(name) {
            sys.warnings.push(at(format!(
                "task `{name}` names itself as its foreground task: it has none (it runs at the top level)"
            )));
        } else if let Some(message) = foreground_finding(&sys, name, &value.text) {
            sys.errors.push(at(message));
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
            tasks: inst.values("Task").map(str::to_owned).collect(),
            all_tasks: inst.has("AllTask"),
            shared: inst.has("Shared"),
            line: inst.line,
        });
    }
    read_hooks(file, &mut sys);
    sys
}

/// The event routines of `CAB_EXEC_HOOKS`.
fn read_hooks(file: &CfgFile, sys: &mut Sys) {
    for inst in file.instances("CAB_EXEC_HOOKS") {
        let (Some(routine), Some(shelf)) = (inst.attr("Routine").and_then(|a| a.value.as_ref()), inst.value("Shelf"))
        else {
            error(file, &mut sys.errors, inst, "an event routine needs `-Routine` and `-Shelf`".to_owned());
            continue;
        };
        let shelf = shelf.to_ascii_uppercase();
        if !SHELVES.contains(&shelf.as_str()) {
            let message = format!("unknown system event `{shelf}` (one of {})", SHELVES.join(", "));
            error(file, &mut sys.errors, inst, message);
            continue;
        }
        let task = inst.value("Task").map(str::to_owned);
        if let Some(name) = &task {
            if sys.task(name).is_none() {
                error(
                    file,
                    &mut sys.errors,
                    inst,
                    format!("event routine `{}` names task `{name}`, which is not configured", routine.text),
                );
                continue;
            }
        }
        sys.hooks.push(ExecHook {
            routine: routine.text.clone(),
            routine_span: routine.span.clone(),
            shelf,
            task,
            all_tasks: inst.has("AllTask"),
            all_motion_tasks: inst.has("AllMotionTask"),
            line: inst.line,
        });
    }
}

impl TaskModule {
    /// Whether the module is loaded into task `task`: shared (one module every task
    /// sees), every task's (`-AllTask`), or one of the tasks `-Task` names.
    pub fn loads_into(&self, task: &str) -> bool {
        self.shared || self.all_tasks || self.tasks.iter().any(|t| t.eq_ignore_ascii_case(task))
    }
}

impl Sys {
    /// The event routines of `shelf` for task `task`, in configuration order.
    pub fn hooks_for(&self, task: &str, shelf: &str) -> Vec<&str> {
        self.hooks.iter().filter(|h| h.shelf == shelf && self.runs_hook(h, task)).map(|h| h.routine.as_str()).collect()
    }

    /// Whether event routine `hook` runs in task `task`: as [`ExecHook::runs_in`] says,
    /// or, with `-AllMotionTask`, because `task` is a motion task.
    pub fn runs_hook(&self, hook: &ExecHook, task: &str) -> bool {
        hook.runs_in(task) || (hook.all_motion_tasks && self.task(task).is_some_and(|t| t.motion_task))
    }
}

impl ExecHook {
    /// Whether the event routine runs in task `task`: every task with `-AllTask`, else
    /// its `-Task`; a hook naming no task belongs to T_ROB1.
    // uncertain: RobotWare's default task for a hook without `-Task`.
    pub fn runs_in(&self, task: &str) -> bool {
        self.all_tasks || self.task.as_deref().unwrap_or("T_ROB1").eq_ignore_ascii_case(task)
    }
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
    // The levels the controller knows (`None` is RobotWare 5's NoSafety), checked here
    // so that `rapid check` reports an unknown one at its line as `rapid run` refuses it.
    if let Some(level) = inst.value("TrustLevel") {
        const LEVELS: [&str; 5] = ["SysFail", "SysHalt", "SysStop", "NoSafety", "None"];
        if !LEVELS.iter().any(|l| l.eq_ignore_ascii_case(level)) {
            let message = format!("task `{name}`: unknown -TrustLevel `{level}` (SysFail, SysHalt, SysStop, NoSafety)");
            error(file, errors, inst, message);
        }
    }
    Some(Task {
        name: name.to_owned(),
        task_type,
        entry: inst.value("Entry").unwrap_or("main").to_owned(),
        entry_span: inst.attr("Entry").and_then(|a| a.value.as_ref()).map(|v| v.span.clone()),
        trust_level: inst.value("TrustLevel").map(str::to_owned),
        motion_task: inst.has("MotionTask"),
        mechanical_unit_group: inst.value("UseMechanicalUnitGroup").map(str::to_owned),
        hidden: inst.has("Hidden"),
        // A task naming itself has no foreground task: RobotWare loads such a line
        // (a SYS.cfg a controller wrote has one, on a STATIC task), and a task cannot
        // wait for itself to idle.
        // uncertain: what RobotWare does with it; running at the top level is ours.
        foreground: foreground_attr(inst)
            .and_then(|a| a.value.as_ref())
            .map(|v| v.text.clone())
            .filter(|t| !t.is_empty() && !t.eq_ignore_ascii_case(name)),
        rmq: rmq(file, inst, name, errors),
        line: inst.line,
    })
}

/// The `-Rmq…` attributes of a task; a bad value is reported and the default kept.
fn rmq(file: &CfgFile, inst: &Instance, task: &str, errors: &mut Vec<CfgError>) -> Rmq {
    let mut rmq = Rmq::default();
    if let Some(text) = inst.value("RmqType") {
        match text.to_ascii_lowercase().as_str() {
            "none" => rmq.rmq_type = RmqType::None,
            "internal" => rmq.rmq_type = RmqType::Internal,
            "remote" => rmq.rmq_type = RmqType::Remote,
            _ => error(
                file,
                errors,
                inst,
                format!("task `{task}`: unknown -RmqType `{text}` (None, Internal or Remote)"),
            ),
        }
    }
    if let Some(text) = inst.value("RmqMode") {
        match text.to_ascii_lowercase().as_str() {
            "interrupt" => rmq.synchronous = false,
            "synchronous" => rmq.synchronous = true,
            _ => error(
                file,
                errors,
                inst,
                format!("task `{task}`: unknown -RmqMode `{text}` (Interrupt or Synchronous)"),
            ),
        }
    }
    let mut number = |attr: &str, max: u32, slot: &mut u32| {
        let Some(text) = inst.value(attr) else { return };
        match text.trim().parse::<u32>() {
            Ok(n) if (1..=max).contains(&n) => *slot = n,
            _ => error(file, errors, inst, format!("task `{task}`: -{attr} `{text}` is not a number from 1 to {max}")),
        }
    };
    number("RmqMaxMsgSize", RMQ_MAX_MSG_SIZE, &mut rmq.max_msg_size);
    number("RmqMaxNoOfMsg", RMQ_MAX_NO_OF_MSG, &mut rmq.max_no_of_msg);
    rmq
}

/// A task's foreground task attribute: `-TaskInForeground`, or `-Task_in_forground`, as
/// the SYS.cfg files controllers write spell it.
fn foreground_attr(inst: &Instance) -> Option<&Attr> {
    inst.attr("TaskInForeground").or_else(|| inst.attr("Task_in_forground"))
}

/// What is wrong with task `name` running in the background of `target` (its
/// `-TaskInForeground`, a manifest's `foreground`), if anything: no such task, itself,
/// or a cycle, where each task would wait for the next to be idle and none ever runs.
pub fn foreground_finding(sys: &Sys, name: &str, target: &str) -> Option<String> {
    if target.is_empty() {
        None
    } else if target.eq_ignore_ascii_case(name) {
        Some(format!("task `{name}` cannot run in its own background"))
    } else if sys.task(target).is_none() {
        Some(format!("task `{name}` runs in the background of `{target}`, which is not a task"))
    } else if in_foreground_cycle(sys, name) {
        Some(format!(
            "task `{name}` runs in the background of `{target}`, which runs (through its foreground tasks) in the \
             background of `{name}`: none of them could run"
        ))
    } else {
        None
    }
}

/// Whether following task `name`'s foreground tasks leads back to it.
fn in_foreground_cycle(sys: &Sys, name: &str) -> bool {
    let mut at = name;
    for _ in 0..=sys.tasks.len() {
        match sys.task(at).and_then(|t| t.foreground.as_deref()) {
            Some(next) if next.eq_ignore_ascii_case(name) => return true,
            Some(next) => at = next,
            None => return false,
        }
    }
    false
}
