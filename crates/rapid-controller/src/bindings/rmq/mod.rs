//! RAPID Message Queue (§1.10; option Multitasking): RMQFindSlot, RMQGetSlotName,
//! RMQSendMessage, RMQSendWait, RMQGetMessage, RMQGetMsgHeader, RMQGetMsgData,
//! RMQReadWait, RMQEmptyQueue, IRMQMessage.
//!
//! Each task configured with `-RmqType Internal` or `Remote` has a queue, slot
//! `RMQ_<task>`, holding at most `-RmqMaxNoOfMsg` messages of at most `-RmqMaxMsgSize`
//! bytes. The queues are part of the state all tasks share ([`SharedRmq`], in
//! `Shared::lent`, which the core lends the running task whole); which tasks have a queue, and how it is configured,
//! is the task list's (`rapid_tasks::TaskInfo::rmq`).
//! In interrupt mode (the default) a message is handed to the trap IRMQMessage ordered
//! for its data type, and discarded when none is; in synchronous mode it waits for
//! RMQReadWait (or RMQSendWait's answer). rmqslot data holds a task's number,
//! rmqmessage data a message the task keeps in its own table ([`RmqWaits`], in the
//! task's extension slot).
//!
//! The family is an extension of the interpreter ([`EXTENSION`]): the message model
//! (`model.rs`, `datum.rs`), the queues and the hand-over of a message to its trap
//! ([`RmqHooks`]: `TaskHooks::deliver`) are its own. The interpreter keeps the
//! interrupt mechanism and its source kind (`rapid_vm::ext::InterruptSource::Rmq`,
//! the data type IRMQMessage orders a trap for) and the task's types by name
//! (`rapid_vm::ext::TypeNames`), which only its loader knows.
//!
//! The front ends' side (an RWS client's messages and queues) is here too:
//! [`send_from_outside`], [`open_outside_queue`], [`take_outside_message`] ...

mod datum;
mod model;

pub use datum::{literal, Datum};
pub use model::{OutsideQueue, RmqMessage, SharedRmq};

use std::collections::VecDeque;

use datum::{size, to_datum, to_value, type_of};
use rapid_tasks::{RmqKind, SharedTaskingAccess, TaskingAccess};
use rapid_vm::ext::TypeNames;
use rapid_vm::ext::{call_site, interrupt_number, native, next_due, present, read_literal, task_index};
use rapid_vm::ext::{Ctx, Family, InterruptSource, Resources, StopKind};
use rapid_vm::ext::{Err, Extension, PendingEvent, RapidError, Shared, TaskHooks, TaskState};
use rapid_vm::ext::{Opaque, OpaqueState, Record, Value};

type Res = Result<Option<Value>, RapidError>;

/// How long RMQReadWait and RMQSendWait wait without `\TimeOut`.
// uncertain: 60 s as we remember the manual; WAIT_MAX waits (practically) for ever.
const DEFAULT_TIMEOUT: f64 = 60.0;

/// `\UserDef` when the sender gives none.
// uncertain: the manual's default is not in the public record; -1 marks "none".
const NO_USERDEF: f64 = -1.0;

/// Slots of queues outside the tasks are numbered from here (a task's slot is its
/// index + 1), so that the two never meet.
const OUTSIDE_SLOTS: usize = 1 << 20;

/// Messages a client's queue holds at most, as the front end keeps its own.
const OUTSIDE_MAX_MESSAGES: usize = 1000;

/// Where a slot leads: a task's queue or a client's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Dest {
    Task(usize),
    Outside(usize),
}

/// The task's side of RMQ: the messages its rmqmessage data holds and the wait under
/// way.
#[derive(Debug, Default)]
pub struct RmqWaits {
    /// Messages rmqmessage data holds: `Handle(n)` is `held[n - 1]`.
    held: Vec<RmqMessage>,
    /// The RMQReadWait / RMQSendWait under way: (call depth, pc, started at).
    waiting: Option<(usize, u32, f64)>,
}

impl TaskState for RmqWaits {
    /// PP to Main: waits end (the messages held stay, as they did).
    fn close_all(&mut self) {
        self.waiting = None;
    }
}

/// The RMQ built-ins and the task's held messages.
pub static EXTENSION: Extension =
    Extension { name: "rmq", families: &[&FAMILY], hooks: Some(&HOOKS), init: Some(init) };

/// What the interpreter's loop asks of RMQ: the messages of the task's queue handed to
/// their traps.
pub struct RmqHooks;

/// The hooks of [`EXTENSION`].
pub static HOOKS: RmqHooks = RmqHooks;

impl TaskHooks for RmqHooks {
    /// RMQ logs no events and owes no wait: answered at once, as the fast loop asks
    /// after every built-in call.
    fn after_builtin(&self, _resources: &mut Resources, _now: f64, _events: &mut Vec<PendingEvent>) -> bool {
        false
    }

    /// Interrupt mode of the RAPID Message Queue: each new message of the task's queue
    /// fires the IRMQMessage interrupt ordered for its data type; one that none is
    /// ordered for is discarded.
    // uncertain: the controller also logs a warning for a discarded message; not yet.
    fn deliver(&self, resources: &mut Resources) {
        let Some(rmq) = resources.lent.get::<SharedRmq>() else { return };
        // The common case (no message anywhere) costs no look at the task list.
        if rmq.queues.iter().all(VecDeque::is_empty) {
            return;
        }
        let me = resources.tasks.index();
        let synchronous = resources.tasking().shared.tasks.get(me).is_some_and(|t| t.rmq.synchronous);
        let Some(rmq) = resources.lent.get_mut::<SharedRmq>() else { return };
        if !rmq.has_undispatched(me, synchronous) {
            return;
        }
        let mut fired = Vec::new();
        let table = &resources.interrupts.table;
        let Some(queue) = rmq.queues.get_mut(me) else { return };
        queue.retain_mut(|message| {
            if message.dispatched {
                return true;
            }
            message.dispatched = true;
            let wanted = table.iter().enumerate().find(|(_, slot)| {
                matches!(slot.as_ref().and_then(|i| i.source.as_ref()),
                    Some(InterruptSource::Rmq { datatype, dims })
                        if datatype.eq_ignore_ascii_case(&message.datatype) && *dims == message.dims)
            });
            match wanted {
                Some((idx, _)) => {
                    fired.push(idx as u32 + 1);
                    true
                }
                None => false,
            }
        });
        for number in fired {
            resources.interrupts.fire(number);
        }
    }
}

/// The queues all tasks share, while the task runs.
fn queues<'a>(ctx: &'a Ctx<'_>) -> &'a SharedRmq {
    static NONE: std::sync::LazyLock<SharedRmq> = std::sync::LazyLock::new(SharedRmq::default);
    ctx.resources.lent.get::<SharedRmq>().unwrap_or(&NONE)
}

/// The queues all tasks share, to change.
fn queues_mut<'a>(ctx: &'a mut Ctx<'_>) -> &'a mut SharedRmq {
    ctx.resources.lent.get_or_default::<SharedRmq>()
}

fn init(resources: &mut Resources) {
    resources.extensions.insert(RmqWaits::default());
}

/// The task's held messages and wait, to change.
fn waits<'a>(ctx: &'a mut Ctx<'_>) -> &'a mut RmqWaits {
    ctx.resources.extensions.get_or_default::<RmqWaits>()
}

/// The wait under way, if any.
fn waiting(ctx: &Ctx<'_>) -> Option<(usize, u32, f64)> {
    ctx.resources.extensions.get::<RmqWaits>().and_then(|w| w.waiting)
}

/// The task's own index in the system.
fn me(ctx: &Ctx<'_>) -> usize {
    task_index(ctx)
}

/// The queue an rmqslot argument names; ERR_RMQ_INVALID when it names none (a
/// client's queue closed since counts as none).
fn slot(ctx: &Ctx<'_>, arg: &Value) -> Result<Dest, RapidError> {
    let (_, handle) = ctx.handle_arg(arg, "an rmqslot")?;
    let (tasks, outside) = (&ctx.resources.tasking().shared.tasks, &queues(ctx).outside);
    handle
        .and_then(|h| (h as usize).checked_sub(1))
        .and_then(|n| match n.checked_sub(OUTSIDE_SLOTS) {
            Some(k) => outside.get(k).and_then(Option::as_ref).map(|_| Dest::Outside(k)),
            None => (n < tasks.len()).then_some(Dest::Task(n)),
        })
        .ok_or_else(|| ctx.error(Err::RmqInvalid, "the rmqslot names no queue (RMQFindSlot first)"))
}

/// Stores slot `task` in an rmqslot argument: a task's index, or
/// `OUTSIDE_SLOTS + k` for client queue `k`.
fn store_slot(ctx: &mut Ctx<'_>, arg: &Value, task: usize) -> Result<(), RapidError> {
    let (opaque, _) = ctx.handle_arg(arg, "an rmqslot")?;
    let slot = Opaque { ty: opaque.ty, state: OpaqueState::Handle(task as u32 + 1) };
    ctx.store(arg, Value::Opaque(Box::new(slot)))
}

/// `RMQFindSlot Slot, Name`: the slot of the queue named `RMQ_<task>`.
fn find_slot(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = ctx.string(&args[1])?;
    let tasks = &ctx.resources.tasking().shared.tasks;
    let found =
        tasks.iter().position(|t| t.rmq.kind != RmqKind::None && format!("RMQ_{}", t.name).eq_ignore_ascii_case(&name));
    // A client's queue is found by its name as the client gave it.
    // uncertain: whether RobotWare compares a client queue's name with letter case.
    let outside = || {
        let outside = &queues(ctx).outside;
        outside.iter().position(|q| q.as_ref().is_some_and(|q| q.name.eq_ignore_ascii_case(&name)))
    };
    let Some(slot) = found.or_else(|| outside().map(|k| OUTSIDE_SLOTS + k)) else {
        return Err(ctx.error(Err::RmqName, format!("no RAPID message queue is named `{name}`")));
    };
    store_slot(ctx, &args[0], slot)?;
    Ok(None)
}

/// `RMQGetSlotName(Slot)`: the slot's name.
fn get_slot_name(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = match slot(ctx, &args[0])? {
        Dest::Task(task) => format!("RMQ_{}", ctx.resources.tasking().shared.tasks[task].name),
        Dest::Outside(k) => queues(ctx).outside[k].as_ref().map(|q| q.name.clone()).unwrap_or_default(),
    };
    Ok(Some(Value::Str(name.into())))
}

/// `RMQSendMessage Slot, SendData [\UserDef]`.
fn send_message(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let dest = slot(ctx, &args[0])?;
    let data = ctx.value(&args[1])?;
    let userdef = ctx.opt_num(args.get(2))?.unwrap_or(NO_USERDEF);
    send(ctx, dest, &data, userdef)?;
    Ok(None)
}

/// Puts a message into the queue of `dest`, as the controller checks it.
fn send(ctx: &mut Ctx<'_>, dest: Dest, data: &Value, userdef: f64) -> Result<(), RapidError> {
    let names = &ctx.resources.type_names;
    let (Some((datatype, dims)), Some(datum)) = (type_of(data, names), to_datum(data, names)) else {
        return Err(ctx.error(Err::RmqValue, "only value data can be sent in a message"));
    };
    let sender = me(ctx);
    let task = match dest {
        Dest::Task(task) => task,
        Dest::Outside(k) => {
            return send_outside(ctx, k, RmqMessage { datatype, dims, data: datum, sender, userdef, dispatched: false })
        }
    };
    let config = ctx.resources.tasking().shared.tasks[task].rmq;
    if config.kind == RmqKind::None {
        return Err(ctx.error(Err::RmqInvalid, "the receiving task has no message queue"));
    }
    let size = size(&datum);
    if size > config.max_msg_size as usize {
        let message = format!("a {size}-byte message is larger than the queue's {} bytes", config.max_msg_size);
        return Err(ctx.error(Err::RmqMsgSize, message));
    }
    if queues(ctx).len_of(task) >= config.max_no_of_msg as usize {
        return Err(ctx.error(Err::RmqFull, "the receiving queue is full"));
    }
    let message = RmqMessage { datatype, dims, data: datum, sender, userdef, dispatched: false };
    queues_mut(ctx).queue_mut(task).push_back(message);
    ctx.resources.tasks.shared.epoch += 1;
    Ok(())
}

/// Puts a task's message into client queue `k`: its size limit is the client's.
fn send_outside(ctx: &mut Ctx<'_>, k: usize, message: RmqMessage) -> Result<(), RapidError> {
    let shared = queues_mut(ctx);
    let Some(queue) = shared.outside.get_mut(k).and_then(Option::as_mut) else {
        return Err(ctx.error(Err::RmqInvalid, "the client's queue has been closed"));
    };
    let size = size(&message.data);
    if size > queue.max_msg_size {
        let text = format!("a {size}-byte message is larger than the queue's {} bytes", queue.max_msg_size);
        return Err(ctx.error(Err::RmqMsgSize, text));
    }
    if queue.messages.len() >= OUTSIDE_MAX_MESSAGES {
        return Err(ctx.error(Err::RmqFull, "the receiving queue is full"));
    }
    queue.messages.push_back(message);
    ctx.resources.tasks.shared.epoch += 1;
    Ok(())
}

/// The controller's queues (outside any task's run).
fn rmq_of(shared: &Shared) -> &SharedRmq {
    static NONE: std::sync::LazyLock<SharedRmq> = std::sync::LazyLock::new(SharedRmq::default);
    shared.lent.get::<SharedRmq>().unwrap_or(&NONE)
}

/// The controller's queues to change (put in at their default first).
fn rmq_of_mut(shared: &mut Shared) -> &mut SharedRmq {
    shared.lent.get_or_default::<SharedRmq>()
}

/// Who sent a message that came from outside the tasks (a client of the controller):
/// no task. Its slot (RMQGetMsgHeader `\SenderId`) names no queue, so an answer to
/// it raises ERR_RMQ_INVALID.
// uncertain: the manual does not say what the sender slot of a message from a PC
// application holds.
fn outside_sender(shared: &Shared) -> usize {
    shared.tasking().tasks.len()
}

/// Why a message from outside the tasks was not queued.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum OutsideRefusal {
    /// Not `<datatype>;<value>`, or no literal of the type.
    BadData(String),
    /// A type that cannot be sent from outside yet.
    Unsupported(String),
    /// The queue's rules: no queue, a message too large, the queue full.
    Queue(String),
}

/// Puts a message from outside the tasks into task `task`'s queue (an RWS client's
/// DIPC send to `RMQ_<task>`): `data` as the controller's IPC messages to RAPID carry
/// it, `<datatype>;<value>` (`num;42`, `string;"hi"`, `pos;[1,2,3]`), the value a RAPID
/// literal of the type as the receiving task declares it (`names`, its types), or a
/// one-dimensional array of such values (`num;[1,2,3]`: an array of three num). `from`
/// is the client's own queue, if it gave one that is open: the message's sender slot.
/// The queue's rules are RMQSendMessage's.
// uncertain: RobotWare's text for an array message is not in the public record; an
// aggregate that is no literal of the type is read as an array of it, and arrays of
// two or three dimensions are refused.
pub fn send_from_outside(
    shared: &mut Shared,
    task: usize,
    message: OutsideMessage<'_>,
    names: &TypeNames,
) -> Result<(), OutsideRefusal> {
    use OutsideRefusal::{BadData, Queue, Unsupported};
    let data = message.data;
    let Some((type_name, literal)) = data.split_once(';') else {
        return Err(BadData(format!("`{data}`: a message to a RAPID task is `<datatype>;<value>`")));
    };
    let (type_name, literal) = (type_name.trim(), literal.trim());
    let template = match type_name.to_ascii_lowercase().as_str() {
        "num" => Value::Num(0.0),
        "dnum" => Value::Dnum(0.0),
        "bool" => Value::Bool(false),
        "string" => Value::Str("".into()),
        _ => names.template(type_name).ok_or_else(|| {
            Unsupported(format!("type `{type_name}`: the receiving task has no value type of that name"))
        })?,
    };
    let value = read_literal(literal, &template)
        .or_else(|| array_literal(literal, &template))
        .ok_or_else(|| BadData(format!("`{literal}` is no {type_name} literal (nor an array of {type_name})")))?;
    let (Some((datatype, dims)), Some(datum)) = (type_of(&value, names), to_datum(&value, names)) else {
        return Err(BadData(format!("`{data}` cannot be sent")));
    };
    let Some(config) = shared.tasking().tasks.get(task).map(|t| t.rmq) else {
        return Err(Queue("no such task".to_owned()));
    };
    if config.kind == RmqKind::None {
        return Err(Queue("the task has no message queue (its RmqType is None)".to_owned()));
    }
    let size = size(&datum);
    if size > config.max_msg_size as usize {
        return Err(Queue(format!("a {size}-byte message is larger than the queue's {} bytes", config.max_msg_size)));
    }
    if rmq_of(shared).len_of(task) >= config.max_no_of_msg as usize {
        return Err(Queue("the queue is full".to_owned()));
    }
    let sender = message
        .from
        .and_then(|name| outside_queue(rmq_of(shared), name))
        .map_or_else(|| outside_sender(shared), |k| OUTSIDE_SLOTS + k);
    let userdef = message.userdef;
    let message = RmqMessage { datatype, dims, data: datum, sender, userdef, dispatched: false };
    rmq_of_mut(shared).queue_mut(task).push_back(message);
    shared.tasks.epoch += 1;
    Ok(())
}

/// A client's message to a task, as [`send_from_outside`] takes it.
#[derive(Debug, Clone, Copy)]
pub struct OutsideMessage<'a> {
    /// `<datatype>;<value>`.
    pub data: &'a str,
    pub userdef: f64,
    /// The client's own queue, the message's sender.
    pub from: Option<&'a str>,
}

/// Arrays a message from outside may hold at most.
const MAX_OUTSIDE_ELEMENTS: usize = 10_000;

/// `literal` read as a one-dimensional array of `template`'s type: as many elements as
/// the aggregate has items.
fn array_literal(literal: &str, template: &Value) -> Option<Value> {
    let n = top_level_items(literal)?;
    if n > MAX_OUTSIDE_ELEMENTS {
        return None;
    }
    let shape =
        Value::Array(Box::new(rapid_vm::ext::Array { dims: [n as u32, 0, 0], elems: vec![template.clone(); n] }));
    read_literal(literal, &shape)
}

/// The number of items of an aggregate `[a, b, …]` (outside strings and inner
/// aggregates); `None` when the text is no aggregate.
fn top_level_items(text: &str) -> Option<usize> {
    let inner = text.trim().strip_prefix('[')?.strip_suffix(']')?;
    if inner.trim().is_empty() {
        return None;
    }
    let (mut depth, mut in_string, mut items) = (0usize, false, 1usize);
    for c in inner.chars() {
        match c {
            // A quote inside a string is written twice: it toggles back at once.
            '"' => in_string = !in_string,
            '[' if !in_string => depth += 1,
            ']' if !in_string => depth = depth.checked_sub(1)?,
            ',' if !in_string && depth == 0 => items += 1,
            _ => {}
        }
    }
    Some(items)
}

/// The index of the open client queue named `name` (any letter case).
fn outside_queue(shared: &SharedRmq, name: &str) -> Option<usize> {
    shared.outside.iter().position(|q| q.as_ref().is_some_and(|q| q.name.eq_ignore_ascii_case(name)))
}

/// Opens client queue `name` (its messages at most `max_msg_size` bytes) for the tasks
/// to send to; false when one of that name is open already.
pub fn open_outside_queue(shared: &mut Shared, name: &str, max_msg_size: usize) -> bool {
    let shared = rmq_of_mut(shared);
    if outside_queue(shared, name).is_some() {
        return false;
    }
    let queue = OutsideQueue { name: name.to_owned(), max_msg_size, messages: VecDeque::new() };
    // A closed queue's place is taken again: its old slots then name the new one.
    match shared.outside.iter().position(Option::is_none) {
        Some(k) => shared.outside[k] = Some(queue),
        None => shared.outside.push(Some(queue)),
    }
    true
}

/// Closes client queue `name`, its messages dropped; false when none is open.
pub fn close_outside_queue(shared: &mut Shared, name: &str) -> bool {
    let shared = rmq_of_mut(shared);
    let Some(k) = outside_queue(shared, name) else { return false };
    shared.outside[k] = None;
    true
}

/// Takes the oldest message the tasks sent to client queue `name`: `None` when the
/// queue is empty or not open.
pub fn take_outside_message(shared: &mut Shared, name: &str) -> Option<RmqMessage> {
    let shared = rmq_of_mut(shared);
    let k = outside_queue(shared, name)?;
    shared.outside[k].as_mut()?.messages.pop_front()
}

/// The name of the queue a message's sender slot names: `RMQ_<task>`, a client's
/// queue, or empty for a client without one.
pub fn sender_name(shared: &Shared, sender: usize) -> String {
    match sender.checked_sub(OUTSIDE_SLOTS) {
        Some(k) => rmq_of(shared).outside.get(k).and_then(Option::as_ref).map(|q| q.name.clone()).unwrap_or_default(),
        None => shared.tasking().tasks.get(sender).map(|t| format!("RMQ_{}", t.name)).unwrap_or_default(),
    }
}

/// Keeps `message` in the rmqmessage argument (reusing the entry it holds).
fn hold(ctx: &mut Ctx<'_>, arg: &Value, message: RmqMessage) -> Result<(), RapidError> {
    let (opaque, handle) = ctx.handle_arg(arg, "an rmqmessage")?;
    let held = &mut waits(ctx).held;
    let handle = match handle.and_then(|h| (h as usize).checked_sub(1)).filter(|&i| i < held.len()) {
        Some(i) => {
            held[i] = message;
            i + 1
        }
        None => {
            held.push(message);
            held.len()
        }
    };
    let kept = Opaque { ty: opaque.ty, state: OpaqueState::Handle(handle as u32) };
    ctx.store(arg, Value::Opaque(Box::new(kept)))
}

/// The message an rmqmessage argument holds; ERR_RMQ_INVMSG when none.
fn held(ctx: &Ctx<'_>, arg: &Value) -> Result<RmqMessage, RapidError> {
    let (_, handle) = ctx.handle_arg(arg, "an rmqmessage")?;
    handle
        .and_then(|h| (h as usize).checked_sub(1))
        .and_then(|i| ctx.resources.extensions.get::<RmqWaits>()?.held.get(i))
        .cloned()
        .ok_or_else(|| ctx.error(Err::RmqInvalidMsg, "the rmqmessage holds no message"))
}

/// `RMQGetMessage Message`: takes the first message of the task's queue (in a trap,
/// the one that interrupted); ERR_RMQ_NOMSG when there is none.
fn get_message(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let me = me(ctx);
    let synchronous = ctx.resources.tasking().shared.tasks[me].rmq.synchronous;
    let queue = queues_mut(ctx).queue_mut(me);
    let at = queue.iter().position(|m| synchronous || m.dispatched);
    let Some(message) = at.and_then(|i| queue.remove(i)) else {
        return Err(ctx.error(Err::RmqNoMsg, "the task's message queue is empty"));
    };
    hold(ctx, &args[0], message)?;
    Ok(None)
}

/// `RMQGetMsgHeader Message [\Header] [\SenderId] [\UserDef]`.
fn get_msg_header(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let message = held(ctx, &args[0])?;
    if present(args.get(1)) {
        let Some(&ty) = ctx.resources.type_names.by_name.get("rmqheader") else {
            return Err(RapidError::fatal("the program has no rmqheader type"));
        };
        let [d1, d2, d3] = message.dims;
        let ndim = message.dims.iter().filter(|&&d| d > 0).count();
        let fields = vec![
            Value::Str(message.datatype.as_str().into()),
            Value::Num(ndim as f32),
            Value::Num(d1 as f32),
            Value::Num(d2 as f32),
            Value::Num(d3 as f32),
        ];
        ctx.store(&args[1], Value::Record(std::rc::Rc::new(Record { ty, fields })))?;
    }
    if present(args.get(2)) {
        store_slot(ctx, &args[2], message.sender)?;
    }
    if present(args.get(3)) {
        ctx.store(&args[3], Value::Num(message.userdef as f32))?;
    }
    Ok(None)
}

/// `RMQGetMsgData Message, Data`: the data, into data of its type and size
/// (ERR_RMQ_VALUE for another type, ERR_RMQ_DIM for another size).
fn get_msg_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let message = held(ctx, &args[0])?;
    let target = ctx.value(&args[1])?;
    let Some((datatype, dims)) = type_of(&target, &ctx.resources.type_names) else {
        return Err(ctx.error(Err::RmqValue, "the data to receive into is not value data"));
    };
    if !datatype.eq_ignore_ascii_case(&message.datatype) {
        let text = format!("the message holds a {}, not a {datatype}", message.datatype);
        return Err(ctx.error(Err::RmqValue, text));
    }
    if dims != message.dims {
        return Err(ctx.error(Err::RmqDim, "the message's array sizes differ from the data's"));
    }
    let Some(value) = to_value(&message.data, &ctx.resources.type_names) else {
        return Err(ctx.error(Err::RmqValue, format!("this task has no type {}", message.datatype)));
    };
    ctx.store(&args[1], value)?;
    Ok(None)
}

/// `RMQReadWait Message [\TimeOut]` (synchronous mode): waits for the next message.
fn read_wait(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    require_synchronous(ctx, "RMQReadWait")?;
    let timeout = ctx.opt_num(args.get(1))?.unwrap_or(DEFAULT_TIMEOUT);
    if let Some(message) = wait_for(ctx, None, timeout)? {
        hold(ctx, &args[0], message)?;
    }
    Ok(None)
}

/// `RMQSendWait Slot, SendData [\UserDef], Message, ReceiveDataType [\Timeout]`
/// (synchronous mode): sends, then waits for a message of ReceiveDataType's type
/// (other messages stay queued).
// uncertain: whether other messages arriving meanwhile are kept or dropped; kept.
fn send_wait(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    require_synchronous(ctx, "RMQSendWait")?;
    if !is_waiting_here(ctx) {
        let dest = slot(ctx, &args[0])?;
        let data = ctx.value(&args[1])?;
        let userdef = ctx.opt_num(args.get(2))?.unwrap_or(NO_USERDEF);
        send(ctx, dest, &data, userdef)?;
    }
    let answer = ctx.value(&args[4])?;
    let Some(want) = type_of(&answer, &ctx.resources.type_names) else {
        return Err(ctx.error(Err::RmqValue, "ReceiveDataType is not value data"));
    };
    let timeout = ctx.opt_num(args.get(5))?.unwrap_or(DEFAULT_TIMEOUT);
    if let Some(message) = wait_for(ctx, Some(want), timeout)? {
        hold(ctx, &args[3], message)?;
    }
    Ok(None)
}

fn require_synchronous(ctx: &Ctx<'_>, what: &str) -> Result<(), RapidError> {
    let me = me(ctx);
    if ctx.resources.tasking().shared.tasks[me].rmq.synchronous {
        return Ok(());
    }
    // uncertain: the controller's error for this misuse is not public; execution stops.
    Err(RapidError::fatal(format!("{what} needs the task's message queue in synchronous mode (-RmqMode)")))
}

fn here(ctx: &Ctx<'_>) -> (usize, u32) {
    call_site(ctx)
}

fn is_waiting_here(ctx: &Ctx<'_>) -> bool {
    let here = here(ctx);
    waiting(ctx).is_some_and(|(depth, pc, _)| (depth, pc) == here)
}

/// The first queued message (of type `want` when given), or a wait for one until the
/// deadline (ERR_RMQ_TIMEOUT after it).
fn wait_for(
    ctx: &mut Ctx<'_>,
    want: Option<(String, [u32; 3])>,
    timeout: f64,
) -> Result<Option<RmqMessage>, RapidError> {
    let (depth, pc) = here(ctx);
    let started = match waiting(ctx) {
        Some((d, p, at)) if (d, p) == (depth, pc) => at,
        _ => ctx.time,
    };
    let me = me(ctx);
    let queue = queues_mut(ctx).queue_mut(me);
    let matches = |m: &RmqMessage| {
        want.as_ref().is_none_or(|(name, dims)| m.datatype.eq_ignore_ascii_case(name) && m.dims == *dims)
    };
    if let Some(message) = queue.iter().position(matches).and_then(|i| queue.remove(i)) {
        waits(ctx).waiting = None;
        return Ok(Some(message));
    }
    let deadline = started + timeout.max(0.0);
    if ctx.time >= deadline {
        waits(ctx).waiting = None;
        return Err(ctx.error(Err::RmqTimeout, "no message came within the time-out"));
    }
    waits(ctx).waiting = Some((depth, pc, started));
    let next = next_due(ctx).map_or(deadline, |due| due.min(deadline));
    ctx.wait = Some((next - ctx.time).max(1e-6));
    ctx.stop = StopKind::Repeat;
    Ok(None)
}

/// `RMQEmptyQueue`: drops every message of the task's queue.
fn empty_queue(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let me = me(ctx);
    queues_mut(ctx).queue_mut(me).clear();
    Ok(None)
}

/// `IRMQMessage InterruptDataType, Interrupt`: a trap for every message of the
/// sample's data type (interrupt mode).
fn irmq_message(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let sample = ctx.value(&args[0])?;
    let Some((datatype, dims)) = type_of(&sample, &ctx.resources.type_names) else {
        return Err(ctx.error(Err::RmqValue, "InterruptDataType is not value data"));
    };
    let n = interrupt_number(ctx, &args[1])?;
    if let Some(interrupt) = ctx.resources.interrupts.get_mut(n) {
        interrupt.source = Some(InterruptSource::Rmq { datatype, dims });
    }
    Ok(None)
}

static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("RMQFindSlot", find_slot),
        native("RMQGetSlotName", get_slot_name),
        native("RMQSendMessage", send_message),
        native("RMQSendWait", send_wait),
        native("RMQGetMessage", get_message),
        native("RMQGetMsgHeader", get_msg_header),
        native("RMQGetMsgData", get_msg_data),
        native("RMQReadWait", read_wait),
        native("RMQEmptyQueue", empty_queue),
        native("IRMQMessage", irmq_message),
    ],
};
