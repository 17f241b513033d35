//! RAPID Message Queues for front ends, as RobotWare's "RAPID Message Queue" option
//! connects PC applications: an RWS client's DIPC message to `RMQ_<task>` goes into
//! the task's queue (the program takes it with IRMQMessage's trap or RMQReadWait, as
//! a message of another task), naming the client's own queue as its sender; a
//! client's queue opened here is a slot the tasks find by name (RMQFindSlot) or by
//! the sender of a message (RMQGetMsgHeader `\SenderId`) and send to, and the client
//! takes those messages back.

use crate::bindings::rmq::{self, OutsideMessage, OutsideRefusal};

use super::{ApiError, Session};

/// A message a task sent to a client's queue.
#[derive(Debug, Clone, PartialEq)]
pub struct ClientMessage {
    /// `<datatype>;<value>`, as the client's messages to a task are written
    /// (`num;6`, `pos;[1,2,3]`, `num;[4,5,6]` for an array).
    pub data: String,
    /// RMQSendMessage's `\UserDef` (-1 without).
    pub userdef: f64,
    /// The sender's queue: `RMQ_<task>`.
    pub from: String,
}

impl Session {
    /// Whether task `task` has a RAPID Message Queue (`-RmqType` other than None).
    pub fn has_rmq(&self, task: &str) -> Result<bool, ApiError> {
        let idx = self.task_index(task)?;
        Ok(self.controller.tasks[idx].spec.rmq.rmq_type != rapid_config::sys::RmqType::None)
    }

    /// Sends `data`, `<datatype>;<value>` as the controller's IPC messages to RAPID
    /// carry it (`num;42`, `string;"hi"`, `pos;[1,2,3]`; a one-dimensional array as
    /// an aggregate of the type's values, `num;[1,2,3]`), to task `task`'s queue with
    /// `userdef`; `from` is the client's own queue (opened with
    /// [`Session::open_client_queue`]), the message's sender. Refused when the task
    /// has no queue open to clients (`-RmqType Remote`), the task has no type of that
    /// name, the queue is full or the message larger than its messages may be
    /// (RMQSendMessage's rules).
    pub fn send_rmq(&mut self, task: &str, data: &str, userdef: f64, from: Option<&str>) -> Result<(), ApiError> {
        use rapid_config::sys::RmqType;
        let idx = self.task_index(task)?;
        match self.controller.tasks[idx].spec.rmq.rmq_type {
            RmqType::Remote => {}
            RmqType::None => {
                return Err(ApiError::NotFound(format!("task {task} has no RAPID message queue (RmqType None)")))
            }
            // The system parameters: an Internal queue takes messages from the
            // controller's tasks only; Remote ones from clients outside too.
            RmqType::Internal => {
                return Err(ApiError::Refused(format!(
                    "RMQ_{task} takes messages from the controller's tasks only (RmqType Internal, not Remote)"
                )))
            }
        }
        // The receiving task's types: a record travels by its name and is read as
        // that task declares it.
        let names = &self.controller.tasks[idx].loaded.vm.resources().type_names;
        let message = OutsideMessage { data, userdef, from };
        let sent = rmq::send_from_outside(&mut self.controller.shared, idx, message, names);
        self.gather();
        sent.map_err(|refusal| match refusal {
            OutsideRefusal::BadData(why) => ApiError::BadLiteral(why),
            OutsideRefusal::Unsupported(why) => ApiError::Unsupported(why),
            OutsideRefusal::Queue(why) => ApiError::Refused(format!("RMQ_{task}: {why}")),
        })
    }

    /// Opens a client's queue `name` for the tasks to send to (messages of at most
    /// `max_msg_size` bytes, as RMQ counts them); false when it is open already.
    pub fn open_client_queue(&mut self, name: &str, max_msg_size: usize) -> bool {
        rmq::open_outside_queue(&mut self.controller.shared, name, max_msg_size)
    }

    /// Closes a client's queue, the messages in it dropped; false when none was open.
    pub fn close_client_queue(&mut self, name: &str) -> bool {
        rmq::close_outside_queue(&mut self.controller.shared, name)
    }

    /// Takes the oldest message the tasks sent to client queue `name`, if any.
    pub fn read_client_queue(&mut self, name: &str) -> Option<ClientMessage> {
        let shared = &mut self.controller.shared;
        let message = rmq::take_outside_message(shared, name)?;
        Some(ClientMessage {
            data: format!("{};{}", message.datatype, rmq::literal(&message.data)),
            userdef: message.userdef,
            from: rmq::sender_name(shared, message.sender),
        })
    }
}
