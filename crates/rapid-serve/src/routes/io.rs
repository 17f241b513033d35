//! `/rw/iosystem/signals`: the list, one signal by `{network}/{device}/{name}` (or by
//! its name alone), and `?action=set`.
//!
//! Signal names are unique on a controller, so a signal is found by its name; the
//! network and device in the path are not checked against its configuration (the
//! motion-program client addresses virtual signals as `Local/DRV_1/…`, and a real
//! controller answers it).

use std::sync::Arc;

use axum::http::Method;

use super::{not_found, Req, Res};
use crate::model::{number, Item, Reply, RwsError};
use crate::App;

const BASE: &str = "/rw/iosystem/";

/// A signal as a list shows it.
struct SignalView {
    name: String,
    kind: String,
    device: Option<String>,
    value: f64,
}

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    let rest: Vec<&str> = req.segs[2..].iter().map(String::as_str).collect();
    match rest.as_slice() {
        ["signals"] if req.is(Method::GET) => {
            let signals = app.controller.call(|core| signals(&core.session, None)).await?;
            Ok(Reply::Items { base: BASE.into(), items: signals.iter().map(|s| item(s, "ios-signal-li")).collect() })
        }
        ["devices"] if req.is(Method::GET) => {
            let signals = app.controller.call(|core| signals(&core.session, None)).await?;
            let mut devices: Vec<String> = signals.into_iter().filter_map(|s| s.device).collect();
            devices.sort();
            devices.dedup();
            let items = devices
                .into_iter()
                .map(|d| Item::new("ios-device-li", &format!("Local/{d}")).with("name", d).with("lstate", "running"))
                .collect();
            Ok(Reply::Items { base: BASE.into(), items })
        }
        ["networks"] if req.is(Method::GET) => {
            let item = Item::new("ios-network-li", "Local").with("name", "Local").with("lstate", "running");
            Ok(Reply::Items { base: BASE.into(), items: vec![item] })
        }
        ["signals", name] | ["signals", _, _, name] => {
            let name = name.strip_suffix(";state").unwrap_or(name).to_owned();
            signal(app, req, name).await
        }
        _ => Err(not_found(req)),
    }
}

async fn signal(app: &Arc<App>, req: &Req, name: String) -> Res {
    match (req.action(), &req.method) {
        (None, &Method::GET) => {
            let lookup = name.clone();
            let found = app.controller.call(move |core| signals(&core.session, Some(&lookup))).await?;
            let view = found.first().ok_or_else(|| RwsError::not_found(format!("no signal `{name}`")))?;
            Ok(Reply::Items { base: BASE.into(), items: vec![item(view, "ios-signal")] })
        }
        (Some("set"), &Method::POST) => {
            let mode = req.field("mode").unwrap_or("value").to_owned();
            let text = req.field("lvalue").map(str::to_owned);
            app.controller
                .call(move |core| {
                    let found = signals(&core.session, Some(&name));
                    let view = found.first().ok_or_else(|| RwsError::not_found(format!("no signal `{name}`")))?;
                    let value = new_value(view, &mode, text.as_deref())?;
                    core.session.set_signal(&view.name, value).map_err(|e| RwsError::from_api(&e))
                })
                .await??;
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}

/// The value a set asks for: `mode=value` with `lvalue`, or `invert`/`toggle` of a
/// digital signal.
fn new_value(view: &SignalView, mode: &str, text: Option<&str>) -> Result<f64, RwsError> {
    let digital = matches!(view.kind.as_str(), "DI" | "DO");
    match mode {
        "value" => {
            let text = text.ok_or_else(|| RwsError::bad_request("the form field `lvalue` is missing"))?;
            let value = text
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| RwsError::bad_request(format!("lvalue `{text}` is no number")))?;
            if digital && value != 0.0 && value != 1.0 {
                return Err(RwsError::bad_request(format!("lvalue `{text}`: a digital signal is 0 or 1")));
            }
            Ok(value)
        }
        "invert" | "toggle" if digital => Ok(1.0 - view.value),
        other => Err(RwsError::unsupported(format!("mode `{other}` for a {} signal", view.kind))),
    }
}

fn signals(session: &rapid_controller::api::Session, only: Option<&str>) -> Vec<SignalView> {
    let Some(io) = session.controller().io_system() else { return Vec::new() };
    io.defs()
        .iter()
        .filter(|d| only.is_none_or(|name| d.name.eq_ignore_ascii_case(name)))
        .map(|d| SignalView {
            name: d.name.clone(),
            kind: d.kind.rapid_type().trim_start_matches("signal").to_ascii_uppercase(),
            device: d.device.clone(),
            value: io.value_by_name(&d.name).unwrap_or(0.0),
        })
        .collect()
}

fn item(view: &SignalView, class: &str) -> Item {
    // uncertain: a device's network is not in our configuration; RWS lists devices
    // under the `Local` network, as the virtual controller's own devices are.
    let title = match &view.device {
        Some(device) => format!("Local/{device}/{}", view.name),
        None => view.name.clone(),
    };
    Item::new(class, &title)
        .with("name", view.name.clone())
        .with("type", view.kind.clone())
        .with("category", "")
        .with("lvalue", number(view.value))
        .with("lstate", "not simulated")
}
