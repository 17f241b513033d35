//! A task's RAPID Message Queue for front ends: an RWS client's DIPC message to
//! `RMQ_<task>` goes into the task's queue, as RobotWare's "RAPID Message Queue"
//! option delivers messages from PC applications (the program takes it with
//! IRMQMessage's trap or RMQReadWait, as a message of another task).

use rapid_vm::builtins::rmq::{send_from_outside, OutsideRefusal};

use super::{ApiError, Session};

impl Session {
    /// Whether task `task` has a RAPID Message Queue (`-RmqType` other than None).
    pub fn has_rmq(&self, task: &str) -> Result<bool, ApiError> {
        let idx = self.task_index(task)?;
        Ok(self.controller.tasks[idx].spec.rmq.rmq_type != rapid_config::sys::RmqType::None)
    }

    /// Sends `data`, `<datatype>;<value>` as the controller's IPC messages to RAPID
    /// carry it (`num;42`, `string;"hi"`), to task `task`'s queue with `userdef`.
    /// Refused when the task has no queue open to clients (`-RmqType Remote`), the
    /// queue is full or the message larger than its messages may be (RMQSendMessage's
    /// rules).
    pub fn send_rmq(&mut self, task: &str, data: &str, userdef: f64) -> Result<(), ApiError> {
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
        let sent = send_from_outside(&mut self.controller.shared.tasking, idx, data, userdef);
        self.gather();
        sent.map_err(|refusal| match refusal {
            OutsideRefusal::BadData(why) => ApiError::BadLiteral(why),
            OutsideRefusal::Unsupported(why) => ApiError::Unsupported(why),
            OutsideRefusal::Queue(why) => ApiError::Refused(format!("RMQ_{task}: {why}")),
        })
    }
}
