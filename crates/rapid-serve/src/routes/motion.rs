//! `/rw/motionsystem/mechunits`: the robots (ROB_1 is the first task that moves one),
//! each one's `jointtarget` and its `robtarget`: the TCP of `tool` (default tool0, the
//! flange) in the `Base` frame, the `World` or the object frame of `wobj`, computed by
//! the controller (`Session::tcp_pose`) and formatted here.

use std::sync::Arc;

use axum::http::Method;
use rapid_controller::api::motion::{Coordinate, TcpPose};
use rapid_controller::api::{MechUnitView, Session};

use super::{not_found, Req, Res};
use crate::model::{number, Item, Reply, RwsError};
use crate::App;

const BASE: &str = "/rw/motionsystem/";
const EAX: [&str; 6] = ["a", "b", "c", "d", "e", "f"];

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    if !req.is(Method::GET) {
        return Err(not_found(req));
    }
    let rest: Vec<&str> = req.segs[2..].iter().map(String::as_str).collect();
    if let ["mechunits", name, "robtarget"] = rest.as_slice() {
        let frames = Frames::parse(req)?;
        let name = (*name).to_owned();
        let item = app.controller.call(move |core| robtarget_of(&mut core.session, &name, &frames)).await??;
        return Ok(Reply::Items { base: BASE.into(), items: vec![item] });
    }
    let units = app.controller.call(|core| core.session.mechunits()).await?;
    let unit = |name: &str| -> Result<MechUnitView, RwsError> {
        let index = name
            .strip_prefix("ROB_")
            .and_then(|n| n.parse::<usize>().ok())
            .and_then(|n| n.checked_sub(1))
            .filter(|&i| i < units.len())
            .ok_or_else(|| RwsError::not_found(format!("no mechanical unit `{name}`")))?;
        Ok(units[index].clone())
    };
    let items = match rest.as_slice() {
        ["mechunits"] => (1..=units.len())
            .map(|n| {
                let name = format!("ROB_{n}");
                Item::new("ms-mechunit-li", &name).with("mode", "Activated")
            })
            .collect(),
        ["mechunits", name] => {
            let u = unit(name)?;
            vec![Item::new("ms-mechunit", name).with("mode", "Activated").with("task", u.task)]
        }
        ["mechunits", name, "jointtarget"] => vec![jointtarget(&unit(name)?)],
        _ => return Err(not_found(req)),
    };
    Ok(Reply::Items { base: BASE.into(), items })
}

fn jointtarget(u: &MechUnitView) -> Item {
    let mut item = Item::new("ms-jointtarget", "jointtarget");
    for (i, j) in u.joints.iter().enumerate() {
        item = item.with(&format!("rax_{}", i + 1), number(*j));
    }
    for (name, e) in EAX.iter().zip(u.extax) {
        item = item.with(&format!("eax_{name}"), number(e));
    }
    item
}

/// The frames a robtarget is asked in.
#[derive(Debug, Clone)]
struct Frames {
    tool: String,
    wobj: String,
    coordinate: Coordinate,
}

impl Frames {
    fn parse(req: &Req) -> Result<Frames, RwsError> {
        let tool = req.query("tool").filter(|t| !t.is_empty()).unwrap_or("tool0").to_owned();
        let wobj = req.query("wobj").filter(|w| !w.is_empty()).unwrap_or("wobj0").to_owned();
        let coordinate = match req.query("coordinate").unwrap_or("Base") {
            c if c.eq_ignore_ascii_case("Base") => Coordinate::Base,
            c if c.eq_ignore_ascii_case("World") => Coordinate::World,
            c if c.eq_ignore_ascii_case("Wobj") => Coordinate::Wobj,
            c if c.eq_ignore_ascii_case("Tool") => {
                return Err(RwsError::unsupported("robtarget in coordinate `Tool`"));
            }
            other => return Err(RwsError::bad_request(format!("coordinate `{other}`: Base, World, Wobj or Tool"))),
        };
        Ok(Frames { tool, wobj, coordinate })
    }
}

/// The robtarget of mechanical unit `name` in `frames`, on the controller thread.
fn robtarget_of(session: &mut Session, name: &str, frames: &Frames) -> Result<Item, RwsError> {
    let count = session.mechunits().len();
    let index = name
        .strip_prefix("ROB_")
        .and_then(|n| n.parse::<usize>().ok())
        .and_then(|n| n.checked_sub(1))
        .filter(|&i| i < count)
        .ok_or_else(|| RwsError::not_found(format!("no mechanical unit `{name}`")))?;
    let tcp =
        session.tcp_pose(index, &frames.tool, &frames.wobj, frames.coordinate).map_err(|e| RwsError::from_api(&e))?;
    Ok(robtarget(&tcp))
}

fn robtarget(tcp: &TcpPose) -> Item {
    let mut item = Item::new("ms-robtargets", "robtarget");
    for (key, v) in ["x", "y", "z"].iter().zip(tcp.trans) {
        item = item.with(key, number(v));
    }
    for (key, v) in ["q1", "q2", "q3", "q4"].iter().zip(tcp.orient) {
        item = item.with(key, number(v));
    }
    for (key, v) in ["cf1", "cf4", "cf6", "cfx"].iter().zip(tcp.conf) {
        item = item.with(key, v.to_string());
    }
    for (name, e) in EAX.iter().zip(tcp.extax) {
        item = item.with(&format!("eax{name}"), number(e));
    }
    item
}
