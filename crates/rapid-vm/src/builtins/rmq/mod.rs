//! RAPID Message Queue (§1.10; option Multitasking): RMQFindSlot, RMQGetSlotName,
//! RMQSendMessage, RMQSendWait, RMQGetMessage, RMQGetMsgHeader, RMQGetMsgData,
//! RMQReadWait, RMQEmptyQueue, IRMQMessage.
//!
//! Each task configured with `-RmqType Internal` or `Remote` has a queue, slot
//! `RMQ_<task>`, holding at most `-RmqMaxNoOfMsg` messages of at most `-RmqMaxMsgSize`
//! bytes. The queues are part of the state all tasks share (`tasking::SharedTasking`).
//! In interrupt mode (the default) a message is handed to the trap IRMQMessage ordered
//! for its data type, and discarded when none is; in synchronous mode it waits for
//! RMQReadWait (or RMQSendWait's answer). rmqslot data holds a task's number,
//! rmqmessage data a message the task keeps in its own table.

mod datum;

pub use datum::{Datum, TypeNames};

use super::{native, present, Ctx, Family, StopKind};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Opaque, OpaqueState, Record, Value};

type Res = Result<Option<Value>, RapidError>;

/// How long RMQReadWait and RMQSendWait wait without `\TimeOut`.
// uncertain: 60 s as we remember the manual; WAIT_MAX waits (practically) for ever.
const DEFAULT_TIMEOUT: f64 = 60.0;

/// `\UserDef` when the sender gives none.
// uncertain: the manual's default is not in the public record; -1 marks "none".
const NO_USERDEF: f64 = -1.0;

/// One message in a queue.
#[derive(Debug, Clone, PartialEq)]
pub struct RmqMessage {
    /// The data's type name as declared, e.g. `string`, `robjoint`.
    pub datatype: String,
    pub dims: [u32; 3],
    pub data: Datum,
    /// The sending task's index.
    pub sender: usize,
    pub userdef: f64,
    /// Interrupt mode: already handed to a trap (or found to have none).
    pub dispatched: bool,
}

/// The task's side of RMQ.
#[derive(Debug, Default)]
pub struct RmqState {
    /// The task's types, to send records by name and rebuild them on receipt.
    pub names: TypeNames,
    /// Messages rmqmessage data holds: `Handle(n)` is `held[n - 1]`.
    held: Vec<RmqMessage>,
    /// The RMQReadWait / RMQSendWait under way: (call depth, pc, started at).
    waiting: Option<(usize, u32, f64)>,
}

impl RmqState {
    /// PP to Main: waits end.
    pub(crate) fn end_waits(&mut self) {
        self.waiting = None;
    }
}

/// The task's own index in the system.
fn me(ctx: &Ctx<'_>) -> usize {
    ctx.resources.tasking.index()
}

/// The task an rmqslot argument names; ERR_RMQ_INVALID when it names none.
fn slot(ctx: &Ctx<'_>, arg: &Value) -> Result<usize, RapidError> {
    let (_, handle) = ctx.handle_arg(arg, "an rmqslot")?;
    handle
        .and_then(|h| (h as usize).checked_sub(1))
        .filter(|&t| t < ctx.resources.tasking.shared.tasks.len())
        .ok_or_else(|| ctx.error(Err::RmqInvalid, "the rmqslot names no queue (RMQFindSlot first)"))
}

/// Stores task `task`'s slot in an rmqslot argument.
fn store_slot(ctx: &mut Ctx<'_>, arg: &Value, task: usize) -> Result<(), RapidError> {
    let (opaque, _) = ctx.handle_arg(arg, "an rmqslot")?;
    let slot = Opaque { ty: opaque.ty, state: OpaqueState::Handle(task as u32 + 1) };
    ctx.store(arg, Value::Opaque(Box::new(slot)))
}

/// `RMQFindSlot Slot, Name`: the slot of the queue named `RMQ_<task>`.
fn find_slot(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = ctx.string(&args[1])?;
    let tasks = &ctx.resources.tasking.shared.tasks;
    let found = tasks.iter().position(|t| {
        t.rmq.rmq_type != rapid_config::sys::RmqType::None && format!("RMQ_{}", t.name).eq_ignore_ascii_case(&name)
    });
    let Some(task) = found else {
        return Err(ctx.error(Err::RmqName, format!("no RAPID message queue is named `{name}`")));
    };
    store_slot(ctx, &args[0], task)?;
    Ok(None)
}

/// `RMQGetSlotName(Slot)`: the slot's name.
fn get_slot_name(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let task = slot(ctx, &args[0])?;
    let name = format!("RMQ_{}", ctx.resources.tasking.shared.tasks[task].name);
    Ok(Some(Value::Str(name.into())))
}

/// `RMQSendMessage Slot, SendData [\UserDef]`.
fn send_message(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let task = slot(ctx, &args[0])?;
    let data = ctx.value(&args[1])?;
    let userdef = ctx.opt_num(args.get(2))?.unwrap_or(NO_USERDEF);
    send(ctx, task, &data, userdef)?;
    Ok(None)
}

/// Puts a message into task `task`'s queue, as the controller checks it.
fn send(ctx: &mut Ctx<'_>, task: usize, data: &Value, userdef: f64) -> Result<(), RapidError> {
    let names = &ctx.resources.rmq.names;
    let (Some((datatype, dims)), Some(datum)) = (datum::type_of(data, names), datum::to_datum(data, names)) else {
        return Err(ctx.error(Err::RmqValue, "only value data can be sent in a message"));
    };
    let sender = me(ctx);
    let shared = &ctx.resources.tasking.shared;
    let config = shared.tasks[task].rmq;
    if config.rmq_type == rapid_config::sys::RmqType::None {
        return Err(ctx.error(Err::RmqInvalid, "the receiving task has no message queue"));
    }
    let size = datum::size(&datum);
    if size > config.max_msg_size as usize {
        let message = format!("a {size}-byte message is larger than the queue's {} bytes", config.max_msg_size);
        return Err(ctx.error(Err::RmqMsgSize, message));
    }
    if shared.queues.get(task).map_or(0, |q| q.len()) >= config.max_no_of_msg as usize {
        return Err(ctx.error(Err::RmqFull, "the receiving queue is full"));
    }
    let message = RmqMessage { datatype, dims, data: datum, sender, userdef, dispatched: false };
    let shared = &mut ctx.resources.tasking.shared;
    if let Some(queue) = shared.queues.get_mut(task) {
        queue.push_back(message);
    }
    shared.epoch += 1;
    Ok(())
}

/// Who sent a message that came from outside the tasks (a client of the controller):
/// no task. Its slot (RMQGetMsgHeader `\SenderId`) names no queue, so an answer to
/// it raises ERR_RMQ_INVALID.
// uncertain: the manual does not say what the sender slot of a message from a PC
// application holds.
fn outside_sender(shared: &super::tasking::SharedTasking) -> usize {
    shared.tasks.len()
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
/// it, `<datatype>;<value>` (`num;42`, `string;"hi"`), the value a RAPID literal. The
/// queue's rules are RMQSendMessage's. Only atomic value types travel this way yet
/// (num, dnum, bool, string): a record's value cannot be read without its task's type
/// table here, and is refused as not supported.
pub fn send_from_outside(
    shared: &mut super::tasking::SharedTasking,
    task: usize,
    data: &str,
    userdef: f64,
) -> Result<(), OutsideRefusal> {
    use OutsideRefusal::{BadData, Queue, Unsupported};
    let Some((type_name, literal)) = data.split_once(';') else {
        return Err(BadData(format!("`{data}`: a message to a RAPID task is `<datatype>;<value>`")));
    };
    let template = match type_name.trim().to_ascii_lowercase().as_str() {
        "num" => Value::Num(0.0),
        "dnum" => Value::Dnum(0.0),
        "bool" => Value::Bool(false),
        "string" => Value::Str("".into()),
        other => return Err(Unsupported(format!("messages of type `{other}` from outside the tasks"))),
    };
    let value = super::read_literal(literal.trim(), &template)
        .ok_or_else(|| BadData(format!("`{}` is no {} literal", literal.trim(), type_name.trim())))?;
    let names = TypeNames::default();
    let (Some((datatype, dims)), Some(datum)) = (datum::type_of(&value, &names), datum::to_datum(&value, &names))
    else {
        return Err(BadData(format!("`{data}` cannot be sent")));
    };
    let Some(config) = shared.tasks.get(task).map(|t| t.rmq) else { return Err(Queue("no such task".to_owned())) };
    if config.rmq_type == rapid_config::sys::RmqType::None {
        return Err(Queue("the task has no message queue (its RmqType is None)".to_owned()));
    }
    let size = datum::size(&datum);
    if size > config.max_msg_size as usize {
        return Err(Queue(format!("a {size}-byte message is larger than the queue's {} bytes", config.max_msg_size)));
    }
    if shared.queues.get(task).map_or(0, |q| q.len()) >= config.max_no_of_msg as usize {
        return Err(Queue("the queue is full".to_owned()));
    }
    let sender = outside_sender(shared);
    let message = RmqMessage { datatype, dims, data: datum, sender, userdef, dispatched: false };
    if let Some(queue) = shared.queues.get_mut(task) {
        queue.push_back(message);
    }
    shared.epoch += 1;
    Ok(())
}

/// Keeps `message` in the rmqmessage argument (reusing the entry it holds).
fn hold(ctx: &mut Ctx<'_>, arg: &Value, message: RmqMessage) -> Result<(), RapidError> {
    let (opaque, handle) = ctx.handle_arg(arg, "an rmqmessage")?;
    let held = &mut ctx.resources.rmq.held;
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
        .and_then(|i| ctx.resources.rmq.held.get(i))
        .cloned()
        .ok_or_else(|| ctx.error(Err::RmqInvalidMsg, "the rmqmessage holds no message"))
}

/// `RMQGetMessage Message`: takes the first message of the task's queue (in a trap,
/// the one that interrupted); ERR_RMQ_NOMSG when there is none.
fn get_message(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let me = me(ctx);
    let synchronous = ctx.resources.tasking.shared.tasks[me].rmq.synchronous;
    let queue = &mut ctx.resources.tasking.shared.queues[me];
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
        let Some(&ty) = ctx.resources.rmq.names.by_name.get("rmqheader") else {
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
    let Some((datatype, dims)) = datum::type_of(&target, &ctx.resources.rmq.names) else {
        return Err(ctx.error(Err::RmqValue, "the data to receive into is not value data"));
    };
    if !datatype.eq_ignore_ascii_case(&message.datatype) {
        let text = format!("the message holds a {}, not a {datatype}", message.datatype);
        return Err(ctx.error(Err::RmqValue, text));
    }
    if dims != message.dims {
        return Err(ctx.error(Err::RmqDim, "the message's array sizes differ from the data's"));
    }
    let Some(value) = datum::to_value(&message.data, &ctx.resources.rmq.names) else {
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
        let task = slot(ctx, &args[0])?;
        let data = ctx.value(&args[1])?;
        let userdef = ctx.opt_num(args.get(2))?.unwrap_or(NO_USERDEF);
        send(ctx, task, &data, userdef)?;
    }
    let answer = ctx.value(&args[4])?;
    let Some(want) = datum::type_of(&answer, &ctx.resources.rmq.names) else {
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
    if ctx.resources.tasking.shared.tasks[me].rmq.synchronous {
        return Ok(());
    }
    // uncertain: the controller's error for this misuse is not public; execution stops.
    Err(RapidError::fatal(format!("{what} needs the task's message queue in synchronous mode (-RmqMode)")))
}

fn here(ctx: &Ctx<'_>) -> (usize, u32) {
    (ctx.chain.len(), ctx.chain.last().map_or(0, |f| f.position().1))
}

fn is_waiting_here(ctx: &Ctx<'_>) -> bool {
    let here = here(ctx);
    ctx.resources.rmq.waiting.is_some_and(|(depth, pc, _)| (depth, pc) == here)
}

/// The first queued message (of type `want` when given), or a wait for one until the
/// deadline (ERR_RMQ_TIMEOUT after it).
fn wait_for(
    ctx: &mut Ctx<'_>,
    want: Option<(String, [u32; 3])>,
    timeout: f64,
) -> Result<Option<RmqMessage>, RapidError> {
    let (depth, pc) = here(ctx);
    let started = match ctx.resources.rmq.waiting {
        Some((d, p, at)) if (d, p) == (depth, pc) => at,
        _ => ctx.time,
    };
    let me = me(ctx);
    let queue = &mut ctx.resources.tasking.shared.queues[me];
    let matches = |m: &RmqMessage| {
        want.as_ref().is_none_or(|(name, dims)| m.datatype.eq_ignore_ascii_case(name) && m.dims == *dims)
    };
    if let Some(message) = queue.iter().position(matches).and_then(|i| queue.remove(i)) {
        ctx.resources.rmq.waiting = None;
        return Ok(Some(message));
    }
    let deadline = started + timeout.max(0.0);
    if ctx.time >= deadline {
        ctx.resources.rmq.waiting = None;
        return Err(ctx.error(Err::RmqTimeout, "no message came within the time-out"));
    }
    ctx.resources.rmq.waiting = Some((depth, pc, started));
    let next = super::interrupts::next_due(ctx).map_or(deadline, |due| due.min(deadline));
    ctx.wait = Some((next - ctx.time).max(1e-6));
    ctx.stop = StopKind::Repeat;
    Ok(None)
}

/// `RMQEmptyQueue`: drops every message of the task's queue.
fn empty_queue(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let me = me(ctx);
    ctx.resources.tasking.shared.queues[me].clear();
    Ok(None)
}

/// `IRMQMessage InterruptDataType, Interrupt`: a trap for every message of the
/// sample's data type (interrupt mode).
fn irmq_message(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let sample = ctx.value(&args[0])?;
    let Some((datatype, dims)) = datum::type_of(&sample, &ctx.resources.rmq.names) else {
        return Err(ctx.error(Err::RmqValue, "InterruptDataType is not value data"));
    };
    let n = super::interrupts::interrupt_number(ctx, &args[1])?;
    if let Some(interrupt) = ctx.resources.interrupts.get_mut(n) {
        interrupt.source = Some(super::interrupts::Source::Rmq { datatype, dims });
    }
    Ok(None)
}

pub(super) static FAMILY: Family = Family {
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
