//! The built-in families of the controller's side: what a RAPID program reaches of
//! the controller beyond the language (its file devices, its network, its configuration, the message queues
//! between tasks ...). Each is an extension of
//! the interpreter (`rapid_vm::ext::Extension`): its built-ins, the state it keeps
//! per task in the task's extension slot, and the hooks the interpreter's loop calls
//! (closing at PP to Main through `TaskState::close_all`). [`crate::builtin_set`] puts
//! them together with the language's own.
//!
//! What it must not know: the scheduler, the API, the front ends; a family sees its
//! task through `rapid_vm::ext::Ctx` only.

pub mod cfgdata;
pub mod files;
pub mod rmq;
pub mod sockets;
