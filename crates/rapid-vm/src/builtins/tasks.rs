//! What the interpreter core knows of the task system (§1.20), and why: only what the
//! language's own built-ins need.
//!
//! - Which task this is ([`TaskPlace::name`], [`TaskPlace::index`]): ERRSTR_TASK in
//!   ErrWrite's texts, the pendant's and the execution log's task names.
//! - The names of the system's tasks ([`SharedTasks::names`]): the `\TaskRef` /
//!   `\TaskName` arguments of GetDataVal, SetDataVal and Save name another task
//!   ([`other_task`]).
//! - The request to the controller and its reply ([`Request`], [`Reply`], [`ask`]):
//!   those built-ins read, write or save in another task, which only the controller
//!   reaches; extensions ask through it too (another task's robot).
//! - The controller-wide event log ([`SharedTasks::events`]): IError in one task traps
//!   another's errors (`exec/interrupts.rs`).
//! - The event routine running ([`TaskPlace::event`]): EventType.
//! - A change count ([`SharedTasks::epoch`]): a waiting task looks again when it moves.
//!
//! Everything else of multitasking — the tasks' kinds and states, sync points,
//! semaphores, synchronized movement, mechanical unit groups — is the extension crate
//! rapid-tasks'. What this module must not know: any extension, the configuration.

use super::{present, Ctx, StopKind};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// A service a task asks of the controller: another task's data or robot. The task
/// waits (re-checking) until the controller has put the reply in the shared state.
#[derive(Debug, Clone)]
pub enum Request {
    /// GetDataVal with `\TaskName`/`\TaskRef`: module data `name` of task `task`.
    ReadData { task: usize, name: String },
    /// SetDataVal with `\TaskName`/`\TaskRef`: `value` (in the asking task's types).
    WriteData { task: usize, name: String, value: Value },
    /// CJointT/CRobT with `\TaskName`/`\TaskRef`: where task `task`'s robot is.
    Robot { task: usize },
    /// StopMove, StartMove or StopMoveReset with `\AllMotionTasks`: the same
    /// built-in (`name`) for the robots of every other motion task.
    AllMotionTasks { name: &'static str },
    /// Save with `\TaskName`/`\TaskRef`: task `task` saves its module `module`, to
    /// `dest` (host path, path as the program wrote it) or to its own file.
    SaveModule { task: usize, module: String, dest: Option<(std::path::PathBuf, String)> },
}

/// The controller's answer to a [`Request`].
#[derive(Debug, Clone)]
pub enum Reply {
    /// The data's value, in the asking task's types.
    Value(Value),
    /// Written.
    Done,
    /// No module data of that name; or it is a constant (for a write); or of
    /// another type than the value written.
    Missing,
    Constant,
    WrongType,
    /// What an extension answers for another task (where that task's robot is): the
    /// core hands it over without looking inside.
    Extension(ExtensionReply),
    /// The other task could not do it: the error to raise in the asking task.
    Failed(Box<RapidError>),
}

/// An extension's answer to a request another task made (an `Rc`, as the reply is
/// cloned when it is read): only the extension that asked knows its type.
#[derive(Clone)]
pub struct ExtensionReply(pub std::rc::Rc<dyn std::any::Any>);

impl std::fmt::Debug for ExtensionReply {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ExtensionReply(..)")
    }
}

/// What the core shares with the other tasks of a controller (swapped in with
/// `Resources::exchange_shared`).
#[derive(Debug, Clone)]
pub struct SharedTasks {
    /// The system's tasks, in configuration order.
    pub names: Vec<String>,
    /// The event-log entries of every task, as the controller's one event log holds
    /// them (IError in one task sees another's errors): (task index, entry).
    pub events: Vec<(usize, crate::events::Event)>,
    /// A request a task made of the controller, and the reply: (asking task, …).
    pub request: Option<(usize, Request)>,
    pub reply: Option<(usize, Reply)>,
    /// Bumped on every change of the core's shared state a waiting task could be
    /// waiting for, and by an extension that puts something into a task's reach (an
    /// RMQ message: the loop asks the extensions to deliver when it moved); rapid-tasks'
    /// shared state counts its own changes.
    pub epoch: u64,
}

impl Default for SharedTasks {
    /// A system of one task, T_ROB1.
    fn default() -> Self {
        SharedTasks::new(vec!["T_ROB1".into()])
    }
}

impl SharedTasks {
    /// The system's tasks by name, in configuration order.
    pub fn new(names: Vec<String>) -> SharedTasks {
        SharedTasks { names, events: Vec::new(), request: None, reply: None, epoch: 0 }
    }

    /// The index of the task of this name (any letter case).
    pub fn position(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|t| t.eq_ignore_ascii_case(name))
    }

    /// Adds entries task `task` logged to the controller-wide log.
    pub fn log_events(&mut self, task: usize, entries: &[crate::events::Event]) {
        if entries.is_empty() {
            return;
        }
        self.events.extend(entries.iter().map(|e| (task, e.clone())));
        self.epoch += 1;
    }
}

/// The task's own place in the system: who it is, the shared view.
#[derive(Debug, Clone, Default)]
pub struct TaskPlace {
    /// The task's name; empty means T_ROB1 (a program run alone).
    pub me: String,
    pub shared: SharedTasks,
    /// The event routine running now (EventType: EVENT_POWERON 1 … EVENT_STEP 7; 0 none).
    pub event: u8,
    /// The change count ([`SharedTasks::epoch`]) when the extensions last delivered
    /// what reached the task (`TaskHooks::deliver`).
    pub(crate) delivered_at: Option<u64>,
}

impl TaskPlace {
    /// The task's name (T_ROB1 when run alone).
    pub fn name(&self) -> &str {
        if self.me.is_empty() {
            "T_ROB1"
        } else {
            &self.me
        }
    }

    /// Its index in the task list.
    pub fn index(&self) -> usize {
        self.shared.position(self.name()).unwrap_or(0)
    }
}

/// The controller's reply to this task's request, or (first time) the request made:
/// `None` means wait and look again (the instruction is re-run).
pub fn ask(ctx: &mut Ctx<'_>, request: Request) -> Option<Reply> {
    let me = ctx.resources.tasks.index();
    let shared = &mut ctx.resources.tasks.shared;
    if let Some((who, _)) = &shared.reply {
        if *who == me {
            return shared.reply.take().map(|(_, reply)| reply);
        }
    }
    if shared.request.is_none() {
        shared.request = Some((me, request));
    }
    // The controller serves the request after this instruction; a short wait that
    // re-checks lets it (and gives way to a task holding the request slot).
    ctx.wait = Some(1e-6);
    ctx.stop = StopKind::Repeat;
    None
}

/// The index of another task of the system a `taskid | string` pair names, or `None`
/// for the task itself (or no such argument). ERR_TASKNAME for a name the system
/// does not have.
pub fn other_task(ctx: &Ctx<'_>, args: &[Value], first: usize) -> Result<Option<usize>, RapidError> {
    if !present(args.get(first)) && !present(args.get(first + 1)) {
        return Ok(None);
    }
    let task = named_task(ctx, args, first)?;
    let tasks = &ctx.resources.tasks;
    Ok(Some(task).filter(|&task| !tasks.shared.names[task].eq_ignore_ascii_case(tasks.name())))
}

/// The index of the task a `taskid | string` argument pair at parameters `first`,
/// `first + 1` names: a taskid by its data name (`T_ROB2Id` is T_ROB2), a string as
/// written. ERR_TASKNAME for a name the system does not have.
pub fn named_task(ctx: &Ctx<'_>, args: &[Value], first: usize) -> Result<usize, RapidError> {
    let pair = args.get(first..).unwrap_or(&[]);
    let text = pair.iter().take(2).find(|arg| matches!(ctx.value(arg), Ok(Value::Str(_))));
    let name = if let Some(text) = text {
        ctx.string(text)?
    } else {
        let data = super::argname::original_name(ctx.chain, first).unwrap_or_default();
        let lower = data.to_ascii_lowercase();
        lower.strip_suffix("id").map_or(data.to_string(), |stem| data[..stem.len()].to_string())
    };
    let shared = &ctx.resources.tasks.shared;
    shared.position(&name).ok_or_else(|| ctx.error(Err::TaskName, format!("the system has no task `{name}`")))
}
