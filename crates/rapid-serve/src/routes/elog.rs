//! `/rw/elog/{domain}`: the event log newest first (domain 0 is every domain), one
//! entry by `/rw/elog/{domain}/{seq}`, and `?action=clear`. Text is English whatever
//! `lang` asks for.

use std::sync::Arc;

use axum::http::Method;
use serde_json::json;

use super::{not_found, Req, Res};
use crate::elog::Entry;
use crate::model::{Item, Reply, RwsError};
use crate::App;

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    let rest: Vec<&str> = req.segs[2..].iter().map(String::as_str).collect();
    let domain = |text: &str| {
        text.parse::<u32>().map_err(|_| RwsError::bad_request(format!("`{text}` is no event-log domain number")))
    };
    match (rest.as_slice(), req.action(), &req.method) {
        ([d], None, &Method::GET) => {
            let domain = domain(d)?;
            let items = app
                .controller
                .call(move |core| core.elog.newest_first(domain).map(|e| item(domain, e)).collect::<Vec<_>>())
                .await?;
            Ok(Reply::Items { base: format!("/rw/elog/{domain}/"), items })
        }
        ([d, seq], None, &Method::GET) => {
            let domain = domain(d)?;
            let seq: u64 = seq.parse().map_err(|_| RwsError::bad_request(format!("`{seq}` is no sequence number")))?;
            let found = app.controller.call(move |core| core.elog.get(seq).map(|e| item(domain, e))).await?;
            let found = found.ok_or_else(|| RwsError::not_found(format!("no event-log entry {seq}")))?;
            Ok(Reply::Items { base: format!("/rw/elog/{domain}/"), items: vec![found] })
        }
        ([d], Some("clear"), &Method::POST) => {
            let domain = domain(d)?;
            app.controller.call(move |core| core.elog.clear(domain)).await?;
            Ok(Reply::NoContent)
        }
        ([], Some("clearall"), &Method::POST) => {
            app.controller.call(|core| core.elog.clear(0)).await?;
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}

fn item(domain: u32, e: &Entry) -> Item {
    let mut item = Item::new("elog-message-li", &format!("/rw/elog/{domain}/{}", e.seq))
        .with("msgtype", e.msgtype.to_string())
        .with("code", e.code.to_string())
        .with("src-name", e.source.clone())
        .with("tstamp", e.tstamp.clone())
        .with("title", e.title.clone())
        .with("desc", e.args.get(1).cloned().unwrap_or_default())
        .with("conseqs", "")
        .with("causes", "")
        .with("actions", "")
        .with("argc", e.args.len().to_string());
    let argv: Vec<_> = e.args.iter().map(|a| json!({"type": "STRING", "value": a})).collect();
    item.extra.push(("argv".into(), serde_json::Value::Array(argv)));
    item
}
