//! The data model of the RAPID Message Queue (§1.10; option Multitasking): a message,
//! a task's queue configuration, a client's queue, and the task's types a message's
//! data travels by (`datum`). The queues themselves are part of the state all tasks
//! share (`tasking::SharedTasking`), and the interpreter hands a queued message to
//! the trap IRMQMessage ordered for its type (`exec/interrupts.rs`). The RMQ
//! built-ins are the controller's (`rapid_controller::bindings::rmq`).

mod datum;

pub use datum::{literal, size, to_datum, to_value, type_of, Datum, TypeNames};

use std::collections::VecDeque;

/// One message in a queue.
#[derive(Debug, Clone, PartialEq)]
pub struct RmqMessage {
    /// The data's type name as declared, e.g. `string`, `robjoint`.
    pub datatype: String,
    pub dims: [u32; 3],
    pub data: Datum,
    /// The sender's slot number less one: the sending task's index, or a client's
    /// queue (`OUTSIDE_SLOTS` on, `rapid_controller::bindings::rmq`), or the number of tasks for a client without one.
    pub sender: usize,
    pub userdef: f64,
    /// Interrupt mode: already handed to a trap (or found to have none).
    pub dispatched: bool,
}

/// Who may send to a task's queue (the configuration's `-RmqType`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RmqKind {
    /// The task has no queue.
    None,
    /// Other tasks of the controller may send.
    Internal,
    /// Other tasks and clients outside the controller may send.
    Remote,
}

/// A task's RAPID Message Queue as the controller configured it (SYS.cfg `-RmqType`,
/// `-RmqMode`, `-RmqMaxMsgSize`, `-RmqMaxNoOfMsg`); the controller converts its
/// configuration into this, so that the VM need not know the configuration's format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RmqConfig {
    pub kind: RmqKind,
    /// Synchronous mode (RMQReadWait receives); else interrupt mode (IRMQMessage traps).
    pub synchronous: bool,
    /// Bytes of data in one message at most.
    pub max_msg_size: u32,
    /// Messages the queue holds at most.
    pub max_no_of_msg: u32,
}

// The configuration's defaults (ABB's system parameters manual, Controller, Task):
// no queue, interrupt mode, 400 bytes, 5 messages.
impl Default for RmqConfig {
    fn default() -> Self {
        RmqConfig { kind: RmqKind::None, synchronous: false, max_msg_size: 400, max_no_of_msg: 5 }
    }
}

/// A queue of a client of the controller (an RWS client's DIPC queue): the tasks
/// send to it by its name; the client takes the messages.
#[derive(Debug, Clone, PartialEq)]
pub struct OutsideQueue {
    pub name: String,
    /// The largest message it takes, in RMQ's bytes.
    pub max_msg_size: usize,
    pub messages: VecDeque<RmqMessage>,
}

/// The task's types, by which a message's records travel (set when the program is
/// loaded; the robot's built-ins read them too).
#[derive(Debug, Default)]
pub struct RmqState {
    /// The task's types, to send records by name and rebuild them on receipt.
    pub names: TypeNames,
}
