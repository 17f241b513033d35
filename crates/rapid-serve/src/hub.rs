//! Subscriptions: `POST /subscription` names resources (`resources=1&1=/rw/…&1-p=1`),
//! the answer (201) links `ws://HOST/poll/{id}`, and a websocket on that address
//! (subprotocol `robapi2_subscription`, which clients insist is echoed) receives one
//! XHTML document per event, each on one line (the Python client's regexes do not
//! cross lines).
//!
//! Events come from the controller thread on a broadcast channel: a slow websocket
//! never holds the controller up; one that falls more than the channel's capacity
//! behind is closed (code 1011, "events lost"), so a lost event is never silent.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use axum::extract::ws::{CloseFrame, Message, WebSocket};
use rapid_controller::api::Change;
use tokio::sync::broadcast;

use crate::model::{escape, escape_text, number, xhtml_head, RwsError, XHTML_TAIL};

/// Subscriptions kept at most (RobotWare limits them per controller too).
const MAX_SUBSCRIPTIONS: usize = 256;
/// Resources one subscription may name.
const MAX_RESOURCES: usize = 100;
/// How often a websocket checks that its subscription still exists.
const CHECK: Duration = Duration::from_secs(1);

/// Something that happened, as the controller thread reports it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Event {
    Signal {
        name: String,
        value: String,
    },
    Persistent {
        name: String,
        value: String,
    },
    Execution {
        state: String,
    },
    CtrlState {
        state: String,
    },
    OpMode {
        mode: String,
    },
    Elog {
        seq: u64,
    },
    /// A task's program pointer moved while the program stands stopped.
    ProgramPointer {
        task: String,
        routine: String,
        module: String,
        position: String,
    },
    /// A message was sent to a DIPC queue.
    Dipc {
        queue: String,
        data: String,
        userdef: String,
    },
}

impl Event {
    /// The event a change of the controller's stream makes, if RWS has one.
    pub(crate) fn of_change(change: &Change) -> Option<Event> {
        match change {
            Change::Signal { name, value, .. } => Some(Event::Signal { name: name.clone(), value: number(*value) }),
            Change::Persistent { name, value } => Some(Event::Persistent { name: name.clone(), value: value.clone() }),
            // Execution state and event-log entries are told by the core (RWS's own
            // names and numbering); the rest has no RWS resource.
            _ => None,
        }
    }
}

/// A resource a subscription names.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Resource {
    CtrlState,
    OpMode,
    Execution,
    /// `/rw/rapid/symbol/data/RAPID/{task}[/{module}]/{name}`: the path (without
    /// `;value`) and the datum's name.
    Persistent {
        path: String,
        name: String,
    },
    /// `/rw/iosystem/signals/[{network}/{device}/]{name}`: the path and the name.
    Signal {
        path: String,
        name: String,
    },
    /// `/rw/elog/{domain}`.
    Elog {
        domain: u32,
    },
    /// `/rw/rapid/tasks/{task}/pcp;programpointerchange`.
    ProgramPointer {
        task: String,
    },
    /// `/rw/dipc/{queue}`.
    Dipc {
        queue: String,
    },
}

impl Resource {
    /// Parses a resource and checks its priority (2, high, only for signals and
    /// persistents, as the RWS manual says).
    pub(crate) fn parse(text: &str, priority: u8) -> Result<Resource, RwsError> {
        let resource = match text.trim() {
            "/rw/panel/ctrlstate" => Resource::CtrlState,
            "/rw/panel/opmode" => Resource::OpMode,
            "/rw/rapid/execution;ctrlexecstate" => Resource::Execution,
            other => Resource::parse_named(other)
                .ok_or_else(|| RwsError::bad_request(format!("`{other}` is no resource one can subscribe to")))?,
        };
        let high_allowed = matches!(resource, Resource::Signal { .. } | Resource::Persistent { .. });
        match priority {
            0 | 1 => Ok(resource),
            2 if high_allowed => Ok(resource),
            2 => Err(RwsError::bad_request(format!("`{text}`: high priority is for signals and persistents only"))),
            _ => Err(RwsError::bad_request(format!("`{text}`: the priority must be 0, 1 or 2"))),
        }
    }

    fn parse_named(text: &str) -> Option<Resource> {
        if let Some(path) = text.strip_suffix(";value") {
            let rest = path.strip_prefix("/rw/rapid/symbol/data/RAPID/")?;
            let parts: Vec<&str> = rest.split('/').collect();
            if !(2..=3).contains(&parts.len()) || parts.iter().any(|p| p.is_empty()) {
                return None;
            }
            return Some(Resource::Persistent { path: path.to_owned(), name: parts[parts.len() - 1].to_owned() });
        }
        if let Some(path) = text.strip_suffix(";state") {
            let rest = path.strip_prefix("/rw/iosystem/signals/")?;
            let parts: Vec<&str> = rest.split('/').collect();
            if !(parts.len() == 1 || parts.len() == 3) || parts.iter().any(|p| p.is_empty()) {
                return None;
            }
            return Some(Resource::Signal { path: path.to_owned(), name: parts[parts.len() - 1].to_owned() });
        }
        if let Some(task) =
            text.strip_prefix("/rw/rapid/tasks/").and_then(|t| t.strip_suffix("/pcp;programpointerchange"))
        {
            return (!task.is_empty() && !task.contains('/'))
                .then(|| Resource::ProgramPointer { task: task.to_owned() });
        }
        if let Some(queue) = text.strip_prefix("/rw/dipc/") {
            return (!queue.is_empty() && !queue.contains('/')).then(|| Resource::Dipc { queue: queue.to_owned() });
        }
        let domain = text.strip_prefix("/rw/elog/")?.trim_end_matches('/');
        Some(Resource::Elog { domain: domain.parse().ok()? })
    }

    /// The `<li>` this resource shows `event` as, if it is about it.
    fn li(&self, event: &Event) -> Option<String> {
        match (self, event) {
            (Resource::Signal { path, name }, Event::Signal { name: n, value }) if name.eq_ignore_ascii_case(n) => {
                Some(format!(
                    "<li class=\"ios-signalstate-ev\" title=\"{t}\"><a href=\"{t};state\" rel=\"self\"/>\
                     <span class=\"lvalue\">{v}</span><span class=\"lstate\">not simulated</span>\
                     <span class=\"quality\">good</span></li>",
                    t = escape(path),
                    v = escape_text(value)
                ))
            }
            (Resource::Persistent { path, name }, Event::Persistent { name: n, value })
                if name.eq_ignore_ascii_case(n) =>
            {
                // The RWS manual's event names the datum (rap-value-ev); the Python
                // client reads its value from a `rap-data` item on the same line.
                Some(format!(
                    "<li class=\"rap-value-ev\" title=\"{t}\"><a href=\"{t};value\" rel=\"self\"/></li>\
                     <li class=\"rap-data\" title=\"{t}\"><span class=\"value\">{v}</span></li>",
                    t = escape(path),
                    v = escape_text(value)
                ))
            }
            (Resource::Execution, Event::Execution { state }) => Some(format!(
                "<li class=\"rap-ctrlexecstate-ev\" title=\"ctrlexecstate\">\
                 <a href=\"/rw/rapid/execution;ctrlexecstate\" rel=\"self\"/>\
                 <span class=\"ctrlexecstate\">{state}</span></li>"
            )),
            (Resource::CtrlState, Event::CtrlState { state }) => Some(format!(
                "<li class=\"pnl-ctrlstate-ev\" title=\"ctrlstate\"><a href=\"/rw/panel/ctrlstate\" rel=\"self\"/>\
                 <span class=\"ctrlstate\">{state}</span></li>"
            )),
            (Resource::OpMode, Event::OpMode { mode }) => Some(format!(
                "<li class=\"pnl-opmode-ev\" title=\"opmode\"><a href=\"/rw/panel/opmode\" rel=\"self\"/>\
                 <span class=\"opmode\">{mode}</span></li>"
            )),
            (Resource::ProgramPointer { task }, Event::ProgramPointer { task: t, routine, module, position })
                if task.eq_ignore_ascii_case(t) =>
            {
                // uncertain: the spans as `GET …/pcp` has them; the RWS manual's
                // example of this event is not in our sources.
                Some(format!(
                    "<li class=\"pcp-info\" title=\"progpointer\">\
                     <a href=\"/rw/rapid/tasks/{t}/pcp;programpointerchange\" rel=\"self\"/>\
                     <span class=\"beginposition\">{p}</span><span class=\"endposition\">{p}</span>\
                     <span class=\"modulemame\">{m}</span><span class=\"routinename\">{r}</span></li>",
                    t = escape(task),
                    p = escape_text(position),
                    m = escape_text(module),
                    r = escape_text(routine)
                ))
            }
            (Resource::Dipc { queue }, Event::Dipc { queue: q, data, userdef }) if queue == q => Some(format!(
                "<li class=\"dipc-msg-ev\" title=\"{t}\"><a href=\"/rw/dipc/{t}\" rel=\"self\"/>\
                 <span class=\"dipc-data\">{d}</span><span class=\"dipc-userdef\">{u}</span></li>",
                t = escape(queue),
                d = escape_text(data),
                u = escape_text(userdef)
            )),
            (Resource::Elog { domain }, Event::Elog { seq }) => Some(format!(
                "<li class=\"elog-message-ev\" title=\"message\"><a href=\"/rw/elog/{domain}/{seq}\" rel=\"self\"/>\
                 <span class=\"seqnum\">{seq}</span></li>"
            )),
            _ => None,
        }
    }
}

/// The subscriptions by id.
#[derive(Debug, Default)]
pub(crate) struct Hub {
    subs: Mutex<Subs>,
}

#[derive(Debug, Default)]
struct Subs {
    next: u64,
    by_id: HashMap<u64, Arc<Vec<Resource>>>,
    /// Websockets open per subscription.
    sockets: HashMap<u64, usize>,
}

impl Hub {
    fn lock(&self) -> std::sync::MutexGuard<'_, Subs> {
        self.subs.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// A new subscription; its id.
    pub(crate) fn add(&self, resources: Vec<Resource>) -> Result<u64, RwsError> {
        if resources.is_empty() || resources.len() > MAX_RESOURCES {
            return Err(RwsError::bad_request(format!("a subscription names 1 to {MAX_RESOURCES} resources")));
        }
        let mut subs = self.lock();
        if subs.by_id.len() >= MAX_SUBSCRIPTIONS {
            // Clients seldom delete their subscriptions (the Python client only closes
            // its websocket): the oldest one nobody listens to makes room.
            let idle = subs.by_id.keys().filter(|id| subs.sockets.get(id).is_none_or(|&n| n == 0)).min().copied();
            let Some(idle) = idle else {
                return Err(RwsError::busy(format!("too many subscriptions ({MAX_SUBSCRIPTIONS}), all listened to")));
            };
            subs.by_id.remove(&idle);
        }
        subs.next += 1;
        let id = subs.next;
        subs.by_id.insert(id, Arc::new(resources));
        Ok(id)
    }

    pub(crate) fn get(&self, id: u64) -> Option<Arc<Vec<Resource>>> {
        self.lock().by_id.get(&id).cloned()
    }

    /// A websocket of subscription `id` opened (true) or closed.
    fn socket(&self, id: u64, open: bool) {
        let mut subs = self.lock();
        let count = subs.sockets.entry(id).or_insert(0);
        *count = if open { *count + 1 } else { count.saturating_sub(1) };
        if *count == 0 {
            subs.sockets.remove(&id);
        }
    }

    pub(crate) fn remove(&self, id: u64) -> bool {
        self.lock().by_id.remove(&id).is_some()
    }
}

/// The XHTML document a subscription's websocket gets for `event`, if any of its
/// resources is about it: one line.
pub(crate) fn render_event(id: u64, host: &str, resources: &[Resource], event: &Event) -> Option<String> {
    let lis: String = resources.iter().filter_map(|r| r.li(event)).collect();
    if lis.is_empty() {
        return None;
    }
    Some(format!(
        "{}<div class=\"state\"><a href=\"http://{h}/subscription/{id}\" rel=\"group\"></a><ul>{lis}</ul></div>{}",
        xhtml_head("Event"),
        XHTML_TAIL,
        h = escape(host)
    ))
}

/// The body of `POST /subscription`'s answer: the poll link the clients look for
/// (`<a href="ws://…/poll/N" rel="self">`).
pub(crate) fn created_body(id: u64, host: &str) -> String {
    let h = escape(host);
    format!(
        "{}<div class=\"state\"><a href=\"http://{h}/subscription/{id}\" rel=\"group\"></a>\
         <a href=\"ws://{h}/poll/{id}\" rel=\"self\"></a></div>{}",
        xhtml_head("Event"),
        XHTML_TAIL
    )
}

/// Serves one websocket: the subscription's events until the client goes, the
/// subscription is deleted, or the client falls too far behind.
pub(crate) async fn pump(
    mut socket: WebSocket,
    hub: Arc<Hub>,
    id: u64,
    host: String,
    mut events: broadcast::Receiver<Event>,
) {
    let Some(resources) = hub.get(id) else { return };
    hub.socket(id, true);
    serve_socket(&mut socket, &hub, id, &host, &resources, &mut events).await;
    hub.socket(id, false);
}

/// The loop of [`pump`]: until the client goes, the subscription is deleted, or the
/// client falls too far behind.
async fn serve_socket(
    socket: &mut WebSocket,
    hub: &Hub,
    id: u64,
    host: &str,
    resources: &[Resource],
    events: &mut broadcast::Receiver<Event>,
) {
    let mut check = tokio::time::interval(CHECK);
    loop {
        tokio::select! {
            event = events.recv() => match event {
                Ok(event) => {
                    if let Some(text) = render_event(id, host, resources, &event) {
                        if socket.send(Message::Text(text.into())).await.is_err() {
                            return;
                        }
                    }
                }
                Err(broadcast::error::RecvError::Lagged(n)) => {
                    let reason = format!("{n} events lost: the client read too slowly");
                    let _ = socket.send(Message::Close(Some(CloseFrame { code: 1011, reason: reason.into() }))).await;
                    return;
                }
                Err(broadcast::error::RecvError::Closed) => return,
            },
            incoming = socket.recv() => match incoming {
                Some(Ok(Message::Close(_))) | None | Some(Err(_)) => return,
                Some(Ok(_)) => {}
            },
            _ = check.tick() => {
                if hub.get(id).is_none() {
                    let _ = socket.send(Message::Close(None)).await;
                    return;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resources_and_priorities() {
        assert_eq!(Resource::parse("/rw/panel/ctrlstate", 1).unwrap(), Resource::CtrlState);
        assert!(Resource::parse("/rw/panel/ctrlstate", 2).is_err());
        let signal = Resource::parse("/rw/iosystem/signals/Local/DRV_1/di1;state", 2).unwrap();
        assert_eq!(
            signal,
            Resource::Signal { path: "/rw/iosystem/signals/Local/DRV_1/di1".into(), name: "di1".into() }
        );
        let pers = Resource::parse("/rw/rapid/symbol/data/RAPID/T_ROB1/count;value", 1).unwrap();
        assert!(matches!(pers, Resource::Persistent { ref name, .. } if name == "count"));
        assert_eq!(Resource::parse("/rw/elog/0", 1).unwrap(), Resource::Elog { domain: 0 });
        assert!(Resource::parse("/rw/nothing", 1).is_err());
        assert!(Resource::parse("/rw/iosystem/signals/a/b;state", 1).is_err());
        let pcp = Resource::parse("/rw/rapid/tasks/T_ROB1/pcp;programpointerchange", 1).unwrap();
        assert_eq!(pcp, Resource::ProgramPointer { task: "T_ROB1".into() });
        assert_eq!(Resource::parse("/rw/dipc/q1", 1).unwrap(), Resource::Dipc { queue: "q1".into() });
    }

    #[test]
    fn a_full_hub_makes_room_from_the_oldest_subscription_nobody_listens_to() {
        let hub = Hub::default();
        let ids: Vec<u64> = (0..MAX_SUBSCRIPTIONS).map(|_| hub.add(vec![Resource::CtrlState]).unwrap()).collect();
        hub.socket(ids[0], true);
        let newest = hub.add(vec![Resource::OpMode]).unwrap();
        // The first is listened to: the second, the oldest idle one, went.
        assert!(hub.get(ids[0]).is_some() && hub.get(ids[1]).is_none() && hub.get(newest).is_some());
        for &id in &ids[2..] {
            hub.socket(id, true);
        }
        hub.socket(newest, true);
        assert!(hub.add(vec![Resource::OpMode]).is_err(), "all listened to: no room");
        hub.socket(ids[0], false);
        assert!(hub.add(vec![Resource::OpMode]).is_ok());
        assert!(hub.get(ids[0]).is_none());
    }

    #[test]
    fn an_event_is_one_line_the_python_client_parses() {
        let resources = vec![Resource::parse("/rw/iosystem/signals/Local/DRV_1/di1;state", 1).unwrap()];
        let event = Event::Signal { name: "DI1".into(), value: "1".into() };
        let text = render_event(3, "127.0.0.1:80", &resources, &event).unwrap();
        assert!(!text.contains('\n'));
        assert!(text.contains("<li class=\"ios-signalstate-ev\""));
        assert!(text.contains("<a href=\"/rw/iosystem/signals/Local/DRV_1/di1;state\" rel=\"self\"/>"));
        assert!(text.contains("<span class=\"lvalue\">1</span>"));
        let other = Event::Signal { name: "di2".into(), value: "1".into() };
        assert_eq!(render_event(3, "h", &resources, &other), None);
        assert!(created_body(7, "h:1").contains("<a href=\"ws://h:1/poll/7\" rel=\"self\">"));
        // The DIPC event as the Python client's regex reads it: queue, data, userdef.
        let queue = vec![Resource::parse("/rw/dipc/q1", 1).unwrap()];
        let message = Event::Dipc { queue: "q1".into(), data: "hello".into(), userdef: "3".into() };
        let text = render_event(1, "h", &queue, &message).unwrap();
        assert!(text.contains("<li class=\"dipc-msg-ev\" title=\"q1\"><a href=\"/rw/dipc/q1\" rel=\"self\"/><span class=\"dipc-data\">hello</span><span class=\"dipc-userdef\">3</span></li>"), "{text}");
    }
}
