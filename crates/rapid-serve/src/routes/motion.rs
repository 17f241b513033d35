//! `/rw/motionsystem/mechunits`: the robots (ROB_1 is the first task that moves one),
//! each one's `jointtarget` and its `robtarget`: the TCP of `tool` (default tool0, the
//! flange) in the `Base` frame, the `World` or the object frame of `wobj`, the tool and
//! work object read from the robot's task as RAPID data.

use std::sync::Arc;

use axum::http::Method;
use rapid_controller::api::{MechUnitView, Session};
use rapid_motion::pose::{orient, pose, trans};
use rapid_motion::Pose;

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

#[derive(Debug, Clone, Copy, PartialEq)]
enum Coordinate {
    Base,
    World,
    Wobj,
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
    let units = session.mechunits();
    let index = name
        .strip_prefix("ROB_")
        .and_then(|n| n.parse::<usize>().ok())
        .and_then(|n| n.checked_sub(1))
        .filter(|&i| i < units.len())
        .ok_or_else(|| RwsError::not_found(format!("no mechanical unit `{name}`")))?;
    let u = &units[index];
    let flange = pose(u.trans, u.orient);
    let tcp = flange * tool_frame(session, &u.task, &frames.tool)?;
    let base = pose(u.base_trans, u.base_orient);
    let shown = match frames.coordinate {
        Coordinate::Base => tcp,
        Coordinate::World => base * tcp,
        Coordinate::Wobj => object_frame(session, &u.task, &frames.wobj)?.inverse() * base * tcp,
    };
    Ok(robtarget(u, trans(&shown), orient(&shown)))
}

/// The tool's frame on the flange (`tframe` of a tooldata the robot holds).
fn tool_frame(session: &mut Session, task: &str, tool: &str) -> Result<Pose, RwsError> {
    if tool.eq_ignore_ascii_case("tool0") {
        return Ok(Pose::identity());
    }
    if read(session, task, tool, "robhold")? != "TRUE" {
        return Err(RwsError::unsupported(format!("robtarget with the stationary tool `{tool}`")));
    }
    pose_of(&read(session, task, tool, "tframe")?, tool)
}

/// A work object's object frame in the world (`uframe` then `oframe`), for a fixed
/// work object the robot does not hold.
fn object_frame(session: &mut Session, task: &str, wobj: &str) -> Result<Pose, RwsError> {
    if wobj.eq_ignore_ascii_case("wobj0") {
        return Ok(Pose::identity());
    }
    let fixed = read(session, task, wobj, "robhold")? == "FALSE" && read(session, task, wobj, "ufprog")? == "TRUE";
    if !fixed {
        return Err(RwsError::unsupported(format!(
            "robtarget in the work object `{wobj}` (held by the robot or moved by a unit)"
        )));
    }
    Ok(pose_of(&read(session, task, wobj, "uframe")?, wobj)? * pose_of(&read(session, task, wobj, "oframe")?, wobj)?)
}

/// Component `part` of datum `name` of task `task`, as RAPID literal text.
fn read(session: &mut Session, task: &str, name: &str, part: &str) -> Result<String, RwsError> {
    let path = format!("{task}/{name}.{part}");
    session.read_data(&path).map(|d| d.value).map_err(|e| RwsError::from_api(&e))
}

/// A pose literal `[[x,y,z],[q1,q2,q3,q4]]`.
fn pose_of(literal: &str, name: &str) -> Result<Pose, RwsError> {
    let numbers: Vec<f64> = literal
        .split(['[', ']', ','])
        .map(str::trim)
        .filter(|t| !t.is_empty())
        .map(str::parse)
        .collect::<Result<_, _>>()
        .map_err(|_| RwsError::bad_request(format!("`{name}`: `{literal}` is no pose")))?;
    match numbers.as_slice() {
        [x, y, z, q1, q2, q3, q4] => rapid_motion::pose::checked_pose([*x, *y, *z], [*q1, *q2, *q3, *q4])
            .ok_or_else(|| RwsError::bad_request(format!("`{name}`: the orientation is not normalised"))),
        _ => Err(RwsError::bad_request(format!("`{name}`: `{literal}` is no pose"))),
    }
}

fn robtarget(u: &MechUnitView, position: [f64; 3], rotation: [f64; 4]) -> Item {
    let mut item = Item::new("ms-robtargets", "robtarget");
    for (key, v) in ["x", "y", "z"].iter().zip(position) {
        item = item.with(key, number(v));
    }
    for (key, v) in ["q1", "q2", "q3", "q4"].iter().zip(rotation) {
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
