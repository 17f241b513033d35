//! `POST /subscription` (resources `resources=1&1=/rw/…&1-p=1`, answered 201 with the
//! websocket's address) and `DELETE /subscription/{id}`.

use std::sync::Arc;

use axum::http::Method;

use super::{not_found, Req, Res};
use crate::hub::{created_body, Resource};
use crate::model::{Reply, RwsError};
use crate::App;

pub(super) fn route(app: &Arc<App>, req: &Req) -> Res {
    let segs: Vec<&str> = req.segs.iter().map(String::as_str).collect();
    match (segs.as_slice(), &req.method) {
        (["subscription"], &Method::POST) => {
            let mut resources = Vec::new();
            for (_, id) in req.form.iter().filter(|(k, _)| k == "resources") {
                let path = req.need(id)?;
                let priority = match req.field(&format!("{id}-p")).unwrap_or("1").parse::<u8>() {
                    Ok(p) => p,
                    Err(_) => return Err(RwsError::bad_request(format!("the priority of resource {id} is no number"))),
                };
                resources.push(Resource::parse(path, priority)?);
            }
            let id = app.hub.add(resources)?;
            Ok(Reply::Created {
                location: Some(format!("ws://{}/poll/{id}", req.host)),
                body: Some(created_body(id, &req.host)),
            })
        }
        (["subscription", id], &Method::DELETE) => {
            let removed = id.parse::<u64>().ok().is_some_and(|id| app.hub.remove(id));
            if !removed {
                return Err(RwsError::not_found(format!("no subscription `{id}`")));
            }
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}
