//! One program task of the system: its configuration (type, trust level, place in the
//! foreground/background order) and how it is doing.

use rapid_vm::Unhandled;

/// `-Type` of a task (§1.20 任务类型).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TaskKind {
    /// Started with the program, one cycle (`rapid run` is one start).
    Normal,
    /// Started at power on, restarts where it was.
    Static,
    /// Started at power on, restarts from the beginning.
    SemiStatic,
}

/// `-TrustLevel`: what the system does when a STATIC or SEMISTATIC task stops.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TrustLevel {
    /// The default: every NORMAL task stops, the system goes to SYS_FAIL.
    #[default]
    SysFail,
    /// Every NORMAL task stops, motors off.
    SysHalt,
    /// Every NORMAL task stops; they may be restarted.
    SysStop,
    /// Only the task itself stops.
    NoSafety,
}

impl TrustLevel {
    /// The level of a `-TrustLevel` value, any letter case (`None` is RobotWare's
    /// spelling of NoSafety in SYS.cfg).
    pub fn parse(text: &str) -> Option<TrustLevel> {
        Some(match text.to_ascii_lowercase().as_str() {
            "sysfail" => TrustLevel::SysFail,
            "syshalt" => TrustLevel::SysHalt,
            "sysstop" => TrustLevel::SysStop,
            "nosafety" | "none" => TrustLevel::NoSafety,
            _ => return None,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            TrustLevel::SysFail => "SysFail",
            TrustLevel::SysHalt => "SysHalt",
            TrustLevel::SysStop => "SysStop",
            TrustLevel::NoSafety => "NoSafety",
        }
    }
}

/// How a task is configured.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TaskSpec {
    pub name: String,
    pub kind: TaskKind,
    pub trust: TrustLevel,
    /// `-TaskInForeground`: the task this one runs behind (only while it is idle).
    pub foreground: Option<String>,
    /// `-MotionTask`: the task that moves the robot.
    pub motion: bool,
    /// A motion task whose mechanical unit group has a robot with a TCP (a positioner's
    /// task moves external units only).
    pub robot: bool,
    /// Its RAPID Message Queue (`-RmqType` …).
    pub rmq: rapid_config::sys::Rmq,
    /// A task that is no motion task but uses a motion task's mechanical unit group
    /// (SYS.cfg `-UseMechanicalUnitGroup`): that motion task, whose robot its CJointT
    /// and CRobT read.
    pub robot_of: Option<String>,
    /// Which of its files are modules installed shared (their variables are one
    /// object for every task, except TASK VAR).
    pub shared_files: Vec<usize>,
}

impl TaskSpec {
    /// Its message queue as the VM's task state holds it.
    pub fn rmq_config(&self) -> rapid_tasks::RmqConfig {
        use rapid_config::sys::RmqType;
        use rapid_tasks::{RmqConfig, RmqKind};
        let kind = match self.rmq.rmq_type {
            RmqType::None => RmqKind::None,
            RmqType::Internal => RmqKind::Internal,
            RmqType::Remote => RmqKind::Remote,
        };
        let rapid_config::sys::Rmq { synchronous, max_msg_size, max_no_of_msg, .. } = self.rmq;
        RmqConfig { kind, synchronous, max_msg_size, max_no_of_msg }
    }

    /// A NORMAL task named `name` (trust level SysFail, in the foreground, no message
    /// queue, no shared modules) that moves its own robot when `motion`: the task of a
    /// program alone, and what tests and front ends build systems of.
    pub fn normal(name: &str, motion: bool) -> TaskSpec {
        TaskSpec {
            name: name.to_owned(),
            kind: TaskKind::Normal,
            trust: TrustLevel::SysFail,
            foreground: None,
            motion,
            robot: motion,
            rmq: rapid_config::sys::Rmq::default(),
            robot_of: None,
            shared_files: Vec::new(),
        }
    }
}

/// Why a task is no longer running.
#[derive(Debug, Clone, PartialEq)]
pub enum TaskEnd {
    /// Its entry routine returned, or EXIT ran.
    Done,
    /// Stop (or Break).
    Stopped,
    /// ExitCycle ended its one cycle.
    CycleEnded,
    /// An error no handler took.
    Failed(Unhandled),
    /// Stopped by the system, because another task failed (trust level) or the run
    /// ended while it still ran.
    Halted,
}
