//! The router: authentication on every request, `/poll/{id}` websockets, and one
//! dispatcher for the RWS resources (their paths hold `$`, `;` and RAPID names, so
//! they are matched by segments here rather than by route patterns).
//!
//! One module per resource family: `panel` (`/rw/panel`, `/ctrl`, `/rw/system`),
//! `rapid` (execution, tasks, symbols, modules), `io` (signals), `motion`
//! (mechunits), `files` (`/fileservice`), `elog`, `cfg` (the configuration database), `users` (RMMP, mastership, DIPC) and
//! `subscribe` (`/subscription`).

mod cfg;
mod elog;
mod files;
mod io;
mod motion;
mod panel;
mod rapid;
mod subscribe;
mod users;

use std::sync::Arc;

use axum::body::Bytes;
use axum::extract::ws::WebSocketUpgrade;
use axum::extract::{DefaultBodyLimit, Path, RawQuery, Request, State};
use axum::http::{header, HeaderMap, HeaderValue, Method, StatusCode, Uri};
use axum::middleware::{self, Next};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::Router;

use crate::auth::{parse_cookies, Verdict};
use crate::model::{error_response, render, Reply, RwsError};
use crate::App;

pub(crate) use users::Dipc;

/// The largest request body (a file PUT to the file service).
const MAX_BODY: usize = 64 * 1024 * 1024;

/// The whole server's routes.
pub(crate) fn router(app: Arc<App>) -> Router {
    Router::new()
        .route("/poll/{id}", get(poll))
        .route("/", get(crate::pendant::index))
        .route("/pendant/{file}", get(crate::pendant::file))
        .route("/pendant/api/screen", get(crate::pendant::screen))
        .route("/pendant/api/answer", axum::routing::post(crate::pendant::answer))
        .route("/pendant/api/arms", get(crate::pendant::arms))
        .route("/pendant/api/program", get(crate::pendant::program))
        .fallback(dispatch)
        .layer(DefaultBodyLimit::max(MAX_BODY))
        .layer(middleware::from_fn(refuse_huge))
        .layer(middleware::from_fn_with_state(app.clone(), authenticate))
        .with_state(app)
}

/// A request as the resources see it.
pub(crate) struct Req {
    pub(crate) method: Method,
    /// The path's segments, percent-decoded, empty ones dropped.
    pub(crate) segs: Vec<String>,
    pub(crate) query: Vec<(String, String)>,
    /// The form fields of a urlencoded body (POST).
    pub(crate) form: Vec<(String, String)>,
    pub(crate) body: Bytes,
    pub(crate) host: String,
}

impl Req {
    /// The first query parameter `key`.
    pub(crate) fn query(&self, key: &str) -> Option<&str> {
        self.query.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }

    /// The first form field `key`.
    pub(crate) fn field(&self, key: &str) -> Option<&str> {
        self.form.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }

    /// Form field `key`, which the request must have.
    pub(crate) fn need(&self, key: &str) -> Result<&str, RwsError> {
        self.field(key).ok_or_else(|| RwsError::bad_request(format!("the form field `{key}` is missing")))
    }

    pub(crate) fn action(&self) -> Option<&str> {
        self.query("action")
    }

    pub(crate) fn is(&self, method: Method) -> bool {
        self.method == method
    }
}

/// What a resource handler returns.
pub(crate) type Res = Result<Reply, RwsError>;

/// Digest authentication or a session cookie, for every request; a fresh digest
/// login sets both session cookies on the answer.
async fn authenticate(State(app): State<Arc<App>>, request: Request, next: Next) -> Response {
    let cookies = request
        .headers()
        .get_all(header::COOKIE)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .flat_map(parse_cookies)
        .collect::<Vec<_>>();
    let uri = request.uri().path_and_query().map_or_else(|| request.uri().path().to_owned(), |pq| pq.to_string());
    let authorization = request.headers().get(header::AUTHORIZATION).and_then(|v| v.to_str().ok());
    match app.auth.check(request.method().as_str(), &uri, &cookies, authorization) {
        Verdict::Session => {
            if request.uri().path() == "/logout" {
                app.auth.logout(&cookies);
            }
            next.run(request).await
        }
        Verdict::NewSession(id) => {
            let mut response = next.run(request).await;
            for cookie in [format!("-http-session-={id}; Path=/; HttpOnly"), format!("ABBCX={id}; Path=/")] {
                if let Ok(value) = HeaderValue::from_str(&cookie) {
                    response.headers_mut().append(header::SET_COOKIE, value);
                }
            }
            response
        }
        Verdict::Challenge(challenge) => {
            let mut response = StatusCode::UNAUTHORIZED.into_response();
            if let Ok(value) = HeaderValue::from_str(&challenge) {
                response.headers_mut().insert(header::WWW_AUTHENTICATE, value);
            }
            response
        }
    }
}

/// A body announced larger than [`MAX_BODY`] is refused (413) at once, from its
/// `Content-Length`, rather than waited for: the limit alone fails only once that
/// much has come, and a client that announces more than it sends would hold the
/// handler until it hangs up.
async fn refuse_huge(request: Request, next: Next) -> Response {
    let announced = request
        .headers()
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.trim().parse::<u64>().ok());
    if announced.is_some_and(|n| n > MAX_BODY as u64) {
        let json = request.uri().query().is_some_and(|q| q.split('&').any(|p| p == "json=1"));
        let err = RwsError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            crate::model::CODE_BAD_REQUEST,
            format!("the body is larger than {} MiB", MAX_BODY / (1024 * 1024)),
        );
        let mut response = error_response(&err, json);
        // The rest of the body is not read: the connection cannot be reused.
        response.headers_mut().insert(header::CONNECTION, HeaderValue::from_static("close"));
        return response;
    }
    next.run(request).await
}

/// `ws://HOST/poll/{id}`: a subscription's events. A refusal is JSON when `json=1` is
/// asked, as every other answer.
async fn poll(
    State(app): State<Arc<App>>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
    upgrade: Result<WebSocketUpgrade, axum::extract::ws::rejection::WebSocketUpgradeRejection>,
) -> Response {
    let host = host_of(&headers);
    let json = query.is_some_and(|q| q.split('&').any(|p| p == "json=1"));
    let Some(id) = id.parse::<u64>().ok().filter(|id| app.hub.get(*id).is_some()) else {
        return error_response(&RwsError::not_found("no such subscription"), json);
    };
    let Ok(upgrade) = upgrade else {
        return error_response(&RwsError::bad_request("a websocket upgrade is expected here"), json);
    };
    let events = app.controller.events();
    let hub = app.hub.clone();
    upgrade
        .protocols(["robapi2_subscription"])
        .on_upgrade(move |socket| crate::hub::pump(socket, hub, id, host, events))
}

fn host_of(headers: &HeaderMap) -> String {
    headers.get(header::HOST).and_then(|h| h.to_str().ok()).unwrap_or("127.0.0.1").to_owned()
}

/// Every other request: parse it, find its resource, render the answer.
async fn dispatch(State(app): State<Arc<App>>, method: Method, uri: Uri, headers: HeaderMap, body: Bytes) -> Response {
    let query: Vec<(String, String)> =
        form_urlencoded::parse(uri.query().unwrap_or("").as_bytes()).into_owned().collect();
    let json = query.iter().any(|(k, v)| k == "json" && v == "1");
    let Some(segs) = segments(uri.path()) else {
        return error_response(&RwsError::bad_request("the path is not valid UTF-8 once decoded"), json);
    };
    let form = if method == Method::POST { form_urlencoded::parse(&body).into_owned().collect() } else { Vec::new() };
    let req = Req { method, segs, query, form, body, host: host_of(&headers) };
    let host = req.host.clone();
    let reply = route(&app, req).await.unwrap_or_else(Reply::Error);
    render(reply, json, &host)
}

/// The path's segments, percent-decoded (None: not UTF-8).
fn segments(path: &str) -> Option<Vec<String>> {
    path.split('/')
        .filter(|s| !s.is_empty())
        .map(|s| percent_encoding::percent_decode_str(s).decode_utf8().ok().map(|s| s.into_owned()))
        .collect()
}

async fn route(app: &Arc<App>, req: Req) -> Res {
    let first: Vec<&str> = req.segs.iter().take(2).map(String::as_str).collect();
    match first.as_slice() {
        ["rw", "panel"] => panel::route(app, &req).await,
        ["rw", "system"] | ["ctrl", ..] => panel::route_ctrl(app, &req).await,
        ["rw", "rapid"] => rapid::route(app, &req).await,
        ["rw", "iosystem"] => io::route(app, &req).await,
        ["rw", "motionsystem"] => motion::route(app, &req).await,
        ["rw", "elog"] => elog::route(app, &req).await,
        ["rw", "cfg"] => cfg::route(app, &req).await,
        ["rw", "dipc"] | ["rw", "mastership"] | ["users", ..] => users::route(app, &req).await,
        ["fileservice", ..] => files::route(app, &req).await,
        ["subscription", ..] => subscribe::route(app, &req),
        ["logout"] => Ok(Reply::NoContent),
        _ => Err(not_found(&req)),
    }
}

/// The answer for a path no resource has.
pub(crate) fn not_found(req: &Req) -> RwsError {
    RwsError::not_found(format!("no resource {} /{}", req.method, req.segs.join("/")))
}
