//! `/rw/motionsystem/mechunits`: the robots (ROB_1 is the first task that moves one),
//! each one's `jointtarget` and its `robtarget` (the flange, tool0, in its base frame).

use std::sync::Arc;

use axum::http::Method;
use rapid_controller::api::MechUnitView;

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
        ["mechunits", name, "robtarget"] => {
            let u = unit(name)?;
            check_frames(req)?;
            vec![robtarget(&u)]
        }
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

/// Only the flange in the base frame is served yet: `tool0`, coordinate `Base`.
fn check_frames(req: &Req) -> Result<(), RwsError> {
    let tool = req.query("tool").unwrap_or("tool0");
    let coordinate = req.query("coordinate").unwrap_or("Base");
    if !(tool.is_empty() || tool.eq_ignore_ascii_case("tool0")) {
        return Err(RwsError::unsupported(format!("robtarget with tool `{tool}`: only tool0 yet")));
    }
    if !coordinate.eq_ignore_ascii_case("Base") {
        return Err(RwsError::unsupported(format!("robtarget in coordinate `{coordinate}`: only Base yet")));
    }
    Ok(())
}

fn robtarget(u: &MechUnitView) -> Item {
    let mut item = Item::new("ms-robtargets", "robtarget");
    for (key, v) in ["x", "y", "z"].iter().zip(u.trans) {
        item = item.with(key, number(v));
    }
    for (key, v) in ["q1", "q2", "q3", "q4"].iter().zip(u.orient) {
        item = item.with(key, number(v));
    }
    for (key, v) in ["cf1", "cf4", "cf6", "cfx"].iter().zip(u.conf) {
        item = item.with(key, v.to_string());
    }
    for (name, e) in EAX.iter().zip(u.extax) {
        item = item.with(&format!("eax{name}"), number(e));
    }
    item
}
