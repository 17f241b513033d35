//! `/users/rmmp` (remote mastership privilege), `/rw/mastership` and `/rw/dipc`
//! (queues between RWS clients).
//!
//! The virtual controller runs in automatic mode with nobody at the pendant: an RMMP
//! request is granted at once, and mastership is always to be had (requests and
//! releases are accepted and change nothing).
//!
//! DIPC queues are kept here: a client creates its queue, sends to a queue created
//! this way and reads its own. A message sent to a RAPID task's RMQ (`RMQ_T_ROB1`, or
//! the task's name) goes into the task's queue through the controller
//! (`Session::send_rmq`): `dipc-data` is `<datatype>;<value>`, as RobotWare's IPC
//! messages to RAPID are, and `dipc-src-queue-name` (the client's own queue) is the
//! message's sender. A client's queue is opened in the controller too, so that the
//! tasks send to it (RMQFindSlot by its name, or RMQGetMsgHeader's `\SenderId`); a
//! `dipc-read` takes the messages of other clients first, then the tasks'.

use std::collections::{HashMap, VecDeque};
use std::sync::{Arc, Mutex};

use axum::http::{Method, StatusCode};

use super::{not_found, Req, Res};
use crate::model::{Item, Reply, RwsError, CODE_DIPC_EXISTS};
use crate::App;

/// Queues kept at most, and messages per queue.
const MAX_QUEUES: usize = 64;
const MAX_MESSAGES: usize = 1000;

/// One DIPC message.
#[derive(Debug, Clone)]
struct Message {
    data: String,
    userdef: String,
    msgtype: String,
    cmd: String,
    from: String,
}

/// The DIPC queues by name.
#[derive(Debug, Default)]
pub(crate) struct Dipc {
    queues: Mutex<HashMap<String, (usize, VecDeque<Message>)>>,
}

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    let segs: Vec<&str> = req.segs.iter().map(String::as_str).collect();
    match (segs.as_slice(), req.action(), &req.method) {
        // abb_librws registers itself as a local or remote user.
        (["users"], None, &Method::POST) => {
            req.need("username")?;
            Ok(Reply::Created { location: None, body: None })
        }
        (["users", "rmmp"], None, &Method::POST) => match req.need("privilege")? {
            "modify" | "exec" => Ok(Reply::NoContent),
            other => Err(RwsError::bad_request(format!("privilege `{other}`: modify or exec"))),
        },
        (["users", "rmmp"], Some("cancel"), &Method::POST) => Ok(Reply::NoContent),
        (["users", "rmmp", "poll"], None, &Method::GET) => {
            let item = Item::new("user-rmmp-poll", "poll").with("status", "GRANTED").with("privilege", "modify");
            Ok(Reply::Items { base: "/users/".into(), items: vec![item] })
        }
        (["users", "rmmp"], None, &Method::GET) => {
            let item = Item::new("user-rmmp", "rmmp").with("privilege", "modify").with("rmmpheldbyme", "true");
            Ok(Reply::Items { base: "/users/".into(), items: vec![item] })
        }
        (["rw", "mastership", ..], Some("request" | "release"), &Method::POST) => Ok(Reply::NoContent),
        (["rw", "dipc"], Some("dipc-create"), &Method::POST) => {
            let name = req.need("dipc-queue-name")?;
            let size = req.field("dipc-max-msg-size").and_then(|s| s.parse().ok()).unwrap_or(444);
            if is_task_queue(app, name).await? {
                return Err(RwsError::bad_request(format!("`{name}` is a RAPID task's queue name")));
            }
            app.dipc.create(name, size)?;
            let (queue, opened) = (name.to_owned(), name.to_owned());
            // Created in both or in neither.
            match app.controller.call(move |core| core.session.open_client_queue(&opened, size)).await {
                Ok(true) => {}
                Ok(false) | Err(_) => {
                    let _ = app.dipc.remove(&queue);
                    return Err(RwsError::busy(format!("queue `{queue}` cannot be opened to the tasks now")));
                }
            }
            Ok(Reply::Created { location: None, body: None })
        }
        (["rw", "dipc", queue], Some("dipc-send"), &Method::POST) => {
            let message = Message {
                data: req.need("dipc-data")?.to_owned(),
                userdef: req.field("dipc-userdef").unwrap_or("0").to_owned(),
                msgtype: req.field("dipc-msgtype").unwrap_or("1").to_owned(),
                cmd: req.field("dipc-cmd").unwrap_or("111").to_owned(),
                from: req.field("dipc-src-queue-name").unwrap_or("").to_owned(),
            };
            if let Some(task) = task_of_queue(app, queue).await? {
                let userdef = message
                    .userdef
                    .trim()
                    .parse::<f64>()
                    .map_err(|_| RwsError::bad_request(format!("dipc-userdef `{}`: a number", message.userdef)))?;
                let from = Some(message.from).filter(|f| !f.is_empty());
                app.controller
                    .call(move |core| core.session.send_rmq(&task, &message.data, userdef, from.as_deref()))
                    .await?
                    .map_err(|e| RwsError::from_api(&e))?;
                return Ok(Reply::NoContent);
            }
            let event = crate::hub::Event::Dipc {
                queue: (*queue).to_owned(),
                data: message.data.clone(),
                userdef: message.userdef.clone(),
            };
            app.dipc.send(queue, message)?;
            app.controller.publish(event);
            Ok(Reply::NoContent)
        }
        (["rw", "dipc", queue], Some("dipc-read"), &Method::GET) => {
            let mut items = app.dipc.read(queue)?;
            if items.is_empty() {
                let name = (*queue).to_owned();
                if let Some(m) = app.controller.call(move |core| core.session.read_client_queue(&name)).await? {
                    items.push(
                        Item::new("dipc-read-li", queue)
                            .with("dipc-data", m.data)
                            .with("dipc-userdef", crate::model::number(m.userdef))
                            .with("dipc-msgtype", "1")
                            .with("dipc-cmd", "111")
                            .with("queue-name", m.from),
                    );
                }
            }
            Ok(Reply::Items { base: "/rw/dipc/".into(), items })
        }
        (["rw", "dipc", queue], None, &Method::DELETE) => {
            app.dipc.remove(queue)?;
            let name = (*queue).to_owned();
            app.controller.call(move |core| core.session.close_client_queue(&name)).await?;
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}

impl Dipc {
    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<String, (usize, VecDeque<Message>)>> {
        self.queues.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    fn create(&self, name: &str, max_size: usize) -> Result<(), RwsError> {
        if name.is_empty() || name.len() > 64 {
            return Err(RwsError::bad_request("a queue name has 1 to 64 characters"));
        }
        let mut queues = self.lock();
        if queues.contains_key(name) {
            return Err(RwsError::new(StatusCode::BAD_REQUEST, CODE_DIPC_EXISTS, format!("queue `{name}` exists")));
        }
        if queues.len() >= MAX_QUEUES {
            return Err(RwsError::busy(format!("too many queues ({MAX_QUEUES})")));
        }
        queues.insert(name.to_owned(), (max_size, VecDeque::new()));
        Ok(())
    }

    fn send(&self, name: &str, message: Message) -> Result<(), RwsError> {
        let mut queues = self.lock();
        let (max_size, queue) =
            queues.get_mut(name).ok_or_else(|| RwsError::not_found(format!("no queue `{name}`")))?;
        if message.data.len() > *max_size {
            return Err(RwsError::bad_request(format!("the message is longer than the queue's {max_size} bytes")));
        }
        if queue.len() >= MAX_MESSAGES {
            return Err(RwsError::busy(format!("queue `{name}` is full")));
        }
        queue.push_back(message);
        Ok(())
    }

    fn read(&self, name: &str) -> Result<Vec<Item>, RwsError> {
        let mut queues = self.lock();
        let (_, queue) = queues.get_mut(name).ok_or_else(|| RwsError::not_found(format!("no queue `{name}`")))?;
        let Some(m) = queue.pop_front() else { return Ok(Vec::new()) };
        Ok(vec![Item::new("dipc-read-li", name)
            .with("dipc-data", m.data)
            .with("dipc-userdef", m.userdef)
            .with("dipc-msgtype", m.msgtype)
            .with("dipc-cmd", m.cmd)
            .with("queue-name", m.from)])
    }

    fn remove(&self, name: &str) -> Result<(), RwsError> {
        match self.lock().remove(name) {
            Some(_) => Ok(()),
            None => Err(RwsError::not_found(format!("no queue `{name}`"))),
        }
    }
}

/// Whether `name` is a RAPID task's RMQ queue: `RMQ_<task>`, or the task's name,
/// which clients may give for it.
async fn is_task_queue(app: &Arc<App>, name: &str) -> Result<bool, RwsError> {
    Ok(task_of_queue(app, name).await?.is_some())
}

/// The task whose RMQ queue `name` is (`RMQ_<task>` or the task's name), if any.
async fn task_of_queue(app: &Arc<App>, name: &str) -> Result<Option<String>, RwsError> {
    let name = name.to_owned();
    app.controller
        .call(move |core| {
            let bare = name.get(..4).filter(|p| p.eq_ignore_ascii_case("RMQ_")).map_or(name.as_str(), |_| &name[4..]);
            core.session.tasks().into_iter().find(|t| t.name.eq_ignore_ascii_case(bare)).map(|t| t.name)
        })
        .await
}
