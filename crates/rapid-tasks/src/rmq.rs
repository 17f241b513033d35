//! A task's RAPID Message Queue configuration (§1.10), as every task sees it: which
//! tasks have a queue, who may send to it, its limits. Part of [`crate::TaskInfo`]
//! because the task list carries it; the queues, the messages and the RMQ built-ins
//! are the controller's (`rapid_controller::bindings::rmq`).

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
/// configuration into this, so that the tasks need not know the configuration's format.
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
