//! `/rw/panel` (controller state with the motors, operating mode, speed ratio),
//! `/ctrl/$ENV` (where the file devices are, as file-service paths) and `/rw/system`.

use std::sync::Arc;

use axum::http::Method;

use super::{not_found, Req, Res};
use crate::hub::Event;
use crate::model::{Item, Reply, RwsError};
use crate::App;

const BASE: &str = "/rw/panel/";

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    let rest: Vec<&str> = req.segs[2..].iter().map(String::as_str).collect();
    match (rest.as_slice(), req.action()) {
        (["ctrlstate"], None) if req.is(Method::GET) => {
            let state = app.controller.call(|core| core.ctrl_state()).await?;
            Ok(items(Item::new("pnl-ctrlstate", "ctrlstate").with("ctrlstate", state)))
        }
        (["ctrlstate"], Some("setctrlstate")) if req.is(Method::POST) => {
            let on = match req.need("ctrl-state")? {
                "motoron" => true,
                "motoroff" => false,
                other => return Err(RwsError::bad_request(format!("ctrl-state `{other}`: motoron or motoroff"))),
            };
            app.controller.call(move |core| core.session.set_motors(on)).await?;
            Ok(Reply::NoContent)
        }
        (["opmode"], None) if req.is(Method::GET) => {
            let mode = app.controller.call(|core| core.opmode).await?;
            Ok(items(Item::new("pnl-opmode", "opmode").with("opmode", mode)))
        }
        (["opmode"], Some("setopmode")) if req.is(Method::POST) => {
            // The virtual controller is in automatic mode; a manual mode would need
            // the enabling device and reduced speed, which it does not model.
            match req.need("opmode")? {
                "AUTO" | "auto" => {
                    app.controller.call(|core| core.publish(Event::OpMode { mode: "AUTO".into() })).await?;
                    Ok(Reply::NoContent)
                }
                other => Err(RwsError::unsupported(format!(
                    "operating mode `{other}`: this virtual controller runs in AUTO only"
                ))),
            }
        }
        (["speedratio"], None) if req.is(Method::GET) => {
            let ratio = app.controller.call(|core| core.session.speed_override()).await?;
            Ok(items(Item::new("pnl-speedratio", "speedratio").with("speedratio", ratio.round().to_string())))
        }
        (["speedratio"], Some("setspeedratio")) if req.is(Method::POST) => {
            let text = req.need("speed-ratio")?;
            let ratio = text
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|r| (0.0..=100.0).contains(r))
                .ok_or_else(|| RwsError::bad_request(format!("speed-ratio `{text}`: a number from 0 to 100")))?;
            // RWS's speed ratio is the operator's override, in whole percent.
            let ratio = ratio.round();
            app.controller
                .call(move |core| core.session.set_speed_override(ratio))
                .await?
                .map_err(|e| RwsError::from_api(&e))?;
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}

fn items(item: Item) -> Reply {
    Reply::Items { base: BASE.to_owned(), items: vec![item] }
}

/// `/ctrl/$HOME` and the like, and `/rw/system`.
pub(super) async fn route_ctrl(_app: &Arc<App>, req: &Req) -> Res {
    let segs: Vec<&str> = req.segs.iter().map(String::as_str).collect();
    if !req.is(Method::GET) {
        return Err(not_found(req));
    }
    match segs.as_slice() {
        ["ctrl", var] if var.starts_with('$') => {
            let device = super::files::device_name(var).ok_or_else(|| {
                RwsError::bad_request(format!("`{var}`: the variables are $HOME, $TEMP, $RAMDISK and $BACKUP"))
            })?;
            // The value is a file-service path to the device: clients put it after
            // `/fileservice/` (a real controller names a disk path there; ours is the
            // variable itself, which our file service resolves).
            let item = Item::new("ctrl-env", var).with("_value", format!("${device}"));
            Ok(Reply::Items { base: "/ctrl/".into(), items: vec![item] })
        }
        ["rw", "system"] => {
            // uncertain: the fields as abb_librws reads them; the version is the
            // RobotWare release the spec describes.
            let item = Item::new("sys-system", "system")
                .with("major", "6")
                .with("minor", "15")
                .with("build", "0")
                .with("title", "OpenRAPID virtual controller")
                .with("type", "RobotWare")
                .with("description", "OpenRAPID's virtual IRC5 controller")
                .with("date", "")
                .with("mctimestamp", "")
                .with("name", "OpenRAPID")
                .with("rwversion", "6.15.04")
                .with("rwversionname", "RobotWare 6.15.04");
            Ok(Reply::Items { base: "/rw/".into(), items: vec![item] })
        }
        _ => Err(not_found(req)),
    }
}
