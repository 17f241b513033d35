//! The web pendant: a page at `/` (behind the same Digest login and session cookies
//! as every RWS resource) that shows and drives the controller the way an operator's
//! FlexPendant does. Its assets are embedded in the binary (`assets/`), so nothing is
//! fetched from the network and `cargo build` is the whole build.
//!
//! The page talks RWS and the `robapi2_subscription` websocket as any client does;
//! what RWS lacks is served here as small JSON resources under `/pendant/api/`:
//! `screen` (the pendant's lines and the dialogs waiting), `answer` (an operator's
//! answer to a dialog), `arms` (each robot's axes and its arm's points from the
//! kinematic model, polled for the 3D view) and `program` (a task's program pointer
//! and the text of the module it is in). `docs/pendant.md` describes them.

use std::sync::Arc;

use axum::body::Bytes;
use axum::extract::State;
use axum::http::{header, StatusCode, Uri};
use axum::response::{IntoResponse, Response};
use serde_json::{json, Value};

use crate::model::RwsError;
use crate::App;

const INDEX: &str = include_str!("assets/index.html");
const SCRIPT: &str = include_str!("assets/pendant.js");
const STYLE: &str = include_str!("assets/pendant.css");
/// A module larger than this is not shown in the program view.
const MAX_MODULE_TEXT: u64 = 2 * 1024 * 1024;

/// `GET /`: the page.
pub(crate) async fn index() -> Response {
    asset(INDEX, "text/html; charset=utf-8")
}

/// `GET /pendant/{file}`: the page's script and style sheet.
pub(crate) async fn file(axum::extract::Path(name): axum::extract::Path<String>) -> Response {
    match name.as_str() {
        "pendant.js" => asset(SCRIPT, "text/javascript; charset=utf-8"),
        "pendant.css" => asset(STYLE, "text/css; charset=utf-8"),
        _ => (StatusCode::NOT_FOUND, "no such file").into_response(),
    }
}

fn asset(text: &'static str, kind: &'static str) -> Response {
    ([(header::CONTENT_TYPE, kind), (header::CACHE_CONTROL, "no-cache")], text).into_response()
}

fn json_response(value: &Value) -> Response {
    ([(header::CONTENT_TYPE, "application/json")], value.to_string()).into_response()
}

fn error(err: &RwsError) -> Response {
    let body = json!({"error": err.msg});
    (err.status, [(header::CONTENT_TYPE, "application/json")], body.to_string()).into_response()
}

/// `GET /pendant/api/screen`: `{"lines": [...], "prompts": [{"id", "task", "text"}]}`.
pub(crate) async fn screen(State(app): State<Arc<App>>) -> Response {
    let answer = app.controller.call(|core| (core.session.tp_screen(), core.session.prompts())).await;
    match answer {
        Ok((lines, prompts)) => {
            let prompts: Vec<Value> =
                prompts.iter().map(|p| json!({"id": p.id, "task": p.task, "text": p.text})).collect();
            json_response(&json!({"lines": lines, "prompts": prompts}))
        }
        Err(e) => error(&e),
    }
}

/// `POST /pendant/api/answer` with form fields `id` and `answer`: answers a dialog
/// (a number, a function key's number or text, a button's text). 204, or 400 when no
/// such dialog waits.
pub(crate) async fn answer(State(app): State<Arc<App>>, body: Bytes) -> Response {
    let form: Vec<(String, String)> = form_urlencoded::parse(&body).into_owned().collect();
    let field = |k: &str| form.iter().find(|(key, _)| key == k).map(|(_, v)| v.clone());
    let Some(id) = field("id").and_then(|id| id.parse::<u64>().ok()) else {
        return error(&RwsError::bad_request("the form field `id` (a prompt's number) is missing"));
    };
    let text = field("answer").unwrap_or_default();
    match app.controller.call(move |core| core.session.answer(id, &text)).await {
        Ok(Ok(())) => StatusCode::NO_CONTENT.into_response(),
        Ok(Err(e)) => error(&RwsError::from_api(&e)),
        Err(e) => error(&e),
    }
}

/// `GET /pendant/api/arms`: per robot, `task`, `joints` (degrees), `points` (the
/// arm's base, column top, axis 2, axis 3, wrist centre, flange; world, mm) and `tcp`.
pub(crate) async fn arms(State(app): State<Arc<App>>) -> Response {
    match app.controller.call(|core| (core.session.arms(), core.session.time())).await {
        Ok((arms, time)) => {
            let arms: Vec<Value> = arms
                .iter()
                .map(|a| json!({"task": a.task, "joints": a.joints, "points": a.points, "tcp": a.tcp}))
                .collect();
            json_response(&json!({"time": time, "arms": arms}))
        }
        Err(e) => error(&e),
    }
}

/// `GET /pendant/api/program?task=T`: the task's program pointer (`routine`, `line`,
/// `column`, `file`, null when the task has none) and the text of the module file it
/// is in (`text`, null when the file is not on disk).
pub(crate) async fn program(State(app): State<Arc<App>>, uri: Uri) -> Response {
    let query = form_urlencoded::parse(uri.query().unwrap_or("").as_bytes()).into_owned();
    let Some(name) = query.into_iter().find(|(k, _)| k == "task").map(|(_, v)| v) else {
        return error(&RwsError::bad_request("the query parameter `task` is missing"));
    };
    let task = name.clone();
    let at = match app.controller.call(move |core| core.session.program_pointer(&task)).await {
        Ok(Ok(at)) => at,
        Ok(Err(e)) => return error(&RwsError::from_api(&e)),
        Err(e) => return error(&e),
    };
    let Some(at) = at else { return json_response(&json!({"task": name, "pointer": null, "text": null})) };
    let file = at.file.clone();
    let text = tokio::task::spawn_blocking(move || module_text(&file)).await.ok().flatten();
    json_response(&json!({
        "task": name,
        "pointer": {"routine": at.routine, "line": at.line, "column": at.column, "file": at.file},
        "text": text,
    }))
}

/// The text of the module file the program was loaded from, if it is on disk and
/// not too large to show.
fn module_text(file: &str) -> Option<String> {
    let path = std::path::Path::new(file);
    let meta = std::fs::metadata(path).ok()?;
    if !meta.is_file() || meta.len() > MAX_MODULE_TEXT {
        return None;
    }
    let bytes = std::fs::read(path).ok()?;
    // RAPID files are Latin-1; show every byte as its character.
    Some(bytes.iter().map(|&b| b as char).collect())
}
