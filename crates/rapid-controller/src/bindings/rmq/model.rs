//! The data model of the RAPID Message Queue (§1.10; option Multitasking): a message,
//! a client's queue, and the queues every task of the controller shares
//! ([`SharedRmq`], in `Shared::lent`: the core lends it to the running task whole). A message's
//! data travels by its type's name (`datum.rs`); a task's queue configuration is part
//! of the task list (`rapid_tasks::RmqConfig`).

use std::collections::VecDeque;

use super::datum::Datum;

/// One message in a queue.
#[derive(Debug, Clone, PartialEq)]
pub struct RmqMessage {
    /// The data's type name as declared, e.g. `string`, `robjoint`.
    pub datatype: String,
    pub dims: [u32; 3],
    pub data: Datum,
    /// The sender's slot number less one: the sending task's index, or a client's
    /// queue (`OUTSIDE_SLOTS` on), or the number of tasks for a client without one.
    pub sender: usize,
    pub userdef: f64,
    /// Interrupt mode: already handed to a trap (or found to have none).
    pub dispatched: bool,
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

/// The queues all tasks share: handed to whichever task runs, as the task list is.
#[derive(Debug, Clone, Default)]
pub struct SharedRmq {
    /// Each task's RAPID Message Queue, by task index (made as a task is first sent to).
    pub queues: Vec<VecDeque<RmqMessage>>,
    /// The queues of the controller's clients the tasks may send to (RWS DIPC
    /// queues), by slot; a closed one's place is empty until another opens. (A message
    /// put into a queue bumps the core's shared change count, `SharedTasks::epoch`: a
    /// waiting task looks again, the receiver's trap is looked for.)
    pub outside: Vec<Option<OutsideQueue>>,
}

impl SharedRmq {
    /// Task `task`'s queue to change (made empty if it has none yet).
    pub fn queue_mut(&mut self, task: usize) -> &mut VecDeque<RmqMessage> {
        if self.queues.len() <= task {
            self.queues.resize_with(task + 1, VecDeque::new);
        }
        &mut self.queues[task]
    }

    /// How many messages task `task`'s queue holds.
    pub fn len_of(&self, task: usize) -> usize {
        self.queues.get(task).map_or(0, VecDeque::len)
    }

    /// Messages in task `me`'s queue no trap has been looked for yet (interrupt mode,
    /// unless `synchronous`).
    pub(super) fn has_undispatched(&self, me: usize, synchronous: bool) -> bool {
        !synchronous && self.queues.get(me).is_some_and(|q| q.iter().any(|m| !m.dispatched))
    }
}

impl rapid_vm::ext::TaskState for SharedRmq {}
