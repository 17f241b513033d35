//! The one item model every resource answers with, and its two renderings: RWS 1.0's
//! XHTML (the default) and its JSON (`json=1`).
//!
//! An item is what RobotWare writes as `<li class=TYPE title=TITLE>` with one
//! `<span class=KEY>value</span>` per field; in JSON the same item is
//! `{"_type": TYPE, "_title": TITLE, KEY: value, …}` inside
//! `{"_links": {"base": …}, "_embedded": {"_state": [items]}}`. Every value is a
//! string, as RobotWare sends them. Errors carry RobotWare's status code and message,
//! `{"_embedded": {"status": {"code": N, "msg": "…"}}}` (the Python client raises
//! `ABBException(msg, code)` from exactly that).

use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde_json::{json, Map, Value};

/// `Content-Type` of a JSON answer: exactly this, without a charset (the Python
/// client compares the header with `==`).
pub(crate) const JSON: &str = "application/json";
/// `Content-Type` of an XHTML answer.
pub(crate) const XHTML: &str = "application/xhtml+xml;v=1.0";

/// One `<li>` of an answer.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Item {
    pub(crate) class: String,
    pub(crate) title: String,
    /// Fields in order: (span class, text).
    pub(crate) fields: Vec<(String, String)>,
    /// JSON-only structured fields (an event's `argv` list).
    pub(crate) extra: Vec<(String, Value)>,
    /// The item's own address, relative to the answer's base: `<a href=… rel="self"/>`
    /// first inside the `<li>`, `"_links": {"self": {"href": …}}` in JSON.
    pub(crate) link: Option<String>,
    /// Items within the item (a configuration instance's attributes): a `<ul>` after
    /// the fields in XHTML, a list under `key` in JSON.
    pub(crate) children: Option<(String, Vec<Item>)>,
}

impl Item {
    pub(crate) fn new(class: &str, title: &str) -> Item {
        Item {
            class: class.to_owned(),
            title: title.to_owned(),
            fields: Vec::new(),
            extra: Vec::new(),
            link: None,
            children: None,
        }
    }

    /// Gives the item its own address (relative to the answer's base).
    pub(crate) fn linked(mut self, href: impl Into<String>) -> Item {
        self.link = Some(href.into());
        self
    }

    /// Gives the item items of its own, listed under `key` in JSON.
    pub(crate) fn holding(mut self, key: &str, children: Vec<Item>) -> Item {
        self.children = Some((key.to_owned(), children));
        self
    }

    /// Adds a field.
    pub(crate) fn with(mut self, key: &str, value: impl Into<String>) -> Item {
        self.fields.push((key.to_owned(), value.into()));
        self
    }
}

/// What a resource answers.
#[derive(Debug)]
pub(crate) enum Reply {
    /// 200 with items; `base` is the resource's parent, for `_links.base`.
    Items {
        base: String,
        items: Vec<Item>,
    },
    /// 200 with one page of items: `next` is the address of the next page (relative
    /// to `base`), when there is one.
    Page {
        base: String,
        items: Vec<Item>,
        next: Option<String>,
    },
    /// 204, the answer to most actions.
    NoContent,
    /// 201 (a file written, a subscription made) with optional headers and body.
    Created {
        location: Option<String>,
        body: Option<String>,
    },
    /// A file's bytes.
    Bytes(Vec<u8>),
    Error(RwsError),
}

/// An error as RobotWare reports it: HTTP status, its own code and a message.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RwsError {
    pub(crate) status: StatusCode,
    pub(crate) code: i64,
    pub(crate) msg: String,
}

// RobotWare's status codes (negative HRESULT-like numbers). Only the DIPC one is in
// the public record (abb-robot-client tests for it); the others are ours, chosen in
// the same range: uncertain.
/// A resource, symbol, signal or file that does not exist.
pub(crate) const CODE_NOT_FOUND: i64 = -1_073_445_865;
/// A malformed request: a missing or bad form field, a bad value.
pub(crate) const CODE_BAD_REQUEST: i64 = -1_073_445_866;
/// The controller's state forbids it now (the program runs, the motors are off).
pub(crate) const CODE_WRONG_STATE: i64 = -1_073_445_867;
/// Not supported by this virtual controller yet.
pub(crate) const CODE_UNSUPPORTED: i64 = -1_073_445_868;
/// The controller is busy (its queue of requests is full) or did not answer in time.
pub(crate) const CODE_BUSY: i64 = -1_073_445_869;
/// A DIPC queue of that name exists already (abb-robot-client's `try_create_ipc_queue`).
pub(crate) const CODE_DIPC_EXISTS: i64 = -1_073_445_879;

impl RwsError {
    pub(crate) fn new(status: StatusCode, code: i64, msg: impl Into<String>) -> RwsError {
        RwsError { status, code, msg: msg.into() }
    }

    pub(crate) fn bad_request(msg: impl Into<String>) -> RwsError {
        RwsError::new(StatusCode::BAD_REQUEST, CODE_BAD_REQUEST, msg)
    }

    pub(crate) fn not_found(msg: impl Into<String>) -> RwsError {
        RwsError::new(StatusCode::NOT_FOUND, CODE_NOT_FOUND, msg)
    }

    pub(crate) fn wrong_state(msg: impl Into<String>) -> RwsError {
        RwsError::new(StatusCode::CONFLICT, CODE_WRONG_STATE, msg)
    }

    /// Something this virtual controller does not do yet: said so, never guessed.
    pub(crate) fn unsupported(msg: impl Into<String>) -> RwsError {
        RwsError::new(StatusCode::BAD_REQUEST, CODE_UNSUPPORTED, format!("not supported yet: {}", msg.into()))
    }

    pub(crate) fn busy(msg: impl Into<String>) -> RwsError {
        RwsError::new(StatusCode::SERVICE_UNAVAILABLE, CODE_BUSY, msg)
    }

    /// An error of the controller's API, with the HTTP status it maps to.
    pub(crate) fn from_api(err: &rapid_controller::api::ApiError) -> RwsError {
        use rapid_controller::api::ApiError as E;
        let msg = err.to_string();
        match err {
            E::NotFound(_) => RwsError::new(StatusCode::BAD_REQUEST, CODE_NOT_FOUND, msg),
            E::BadPath(_) | E::BadLiteral(_) => RwsError::bad_request(msg),
            E::ReadOnly(_) | E::WrongState(_) | E::Refused(_) => RwsError::wrong_state(msg),
            E::Unsupported(_) => RwsError::new(StatusCode::BAD_REQUEST, CODE_UNSUPPORTED, msg),
            E::Failed(_) => RwsError::new(StatusCode::INTERNAL_SERVER_ERROR, CODE_WRONG_STATE, msg),
        }
    }
}

impl From<RwsError> for Reply {
    fn from(err: RwsError) -> Reply {
        Reply::Error(err)
    }
}

/// Turns a reply into the HTTP answer, as JSON or XHTML.
pub(crate) fn render(reply: Reply, json: bool, host: &str) -> Response {
    match reply {
        Reply::Items { base, items } => {
            let base = format!("http://{host}{base}");
            let (ctype, body) =
                if json { (JSON, items_json(&base, &items)) } else { (XHTML, items_xhtml(&base, &items)) };
            with_type(StatusCode::OK, ctype, body)
        }
        Reply::Page { base, items, next } => {
            let base = format!("http://{host}{base}");
            let (ctype, body) = if json {
                (JSON, page_json(&base, &items, next.as_deref()))
            } else {
                (XHTML, page_xhtml(&base, &items, next.as_deref()))
            };
            with_type(StatusCode::OK, ctype, body)
        }
        Reply::NoContent => StatusCode::NO_CONTENT.into_response(),
        Reply::Created { location, body } => {
            // A Content-Type even without a body: the Python client reads the header
            // of every answer but a 204.
            let mut response = with_type(StatusCode::CREATED, XHTML, body.unwrap_or_default());
            if let Some(value) = location.and_then(|l| HeaderValue::from_str(&l).ok()) {
                response.headers_mut().insert(header::LOCATION, value);
            }
            response
        }
        Reply::Bytes(bytes) => {
            let mut response = (StatusCode::OK, bytes).into_response();
            response.headers_mut().insert(header::CONTENT_TYPE, HeaderValue::from_static("application/octet-stream"));
            response
        }
        Reply::Error(err) => error_response(&err, json),
    }
}

/// An error's answer: its status code and RobotWare's status body.
pub(crate) fn error_response(err: &RwsError, json: bool) -> Response {
    if json {
        let body = json!({"_links": {}, "_embedded": {"_state": [], "status": {"code": err.code, "msg": err.msg}}});
        return with_type(err.status, JSON, body.to_string());
    }
    let body = format!(
        "{}<div class=\"status\"><span class=\"code\">{}</span><span class=\"msg\">{}</span></div>{}",
        xhtml_head("Error"),
        err.code,
        escape(&err.msg),
        XHTML_TAIL
    );
    with_type(err.status, XHTML, body)
}

fn with_type(status: StatusCode, ctype: &'static str, body: String) -> Response {
    let mut response = (status, body).into_response();
    response.headers_mut().insert(header::CONTENT_TYPE, HeaderValue::from_static(ctype));
    response
}

fn items_json(base: &str, items: &[Item]) -> String {
    page_json(base, items, None)
}

fn page_json(base: &str, items: &[Item], next: Option<&str>) -> String {
    let state: Vec<Value> = items.iter().map(item_json).collect();
    let mut links = json!({"base": {"href": base}});
    if let Some(next) = next {
        links["next"] = json!({"href": next});
    }
    json!({"_links": links, "_embedded": {"_state": state}}).to_string()
}

/// One item as JSON: `_type`, `_title`, then its fields.
pub(crate) fn item_json(item: &Item) -> Value {
    let mut object = Map::new();
    object.insert("_type".into(), Value::String(item.class.clone()));
    object.insert("_title".into(), Value::String(item.title.clone()));
    if let Some(link) = &item.link {
        object.insert("_links".into(), json!({"self": {"href": link}}));
    }
    for (key, value) in &item.fields {
        object.insert(key.clone(), Value::String(value.clone()));
    }
    for (key, value) in &item.extra {
        object.insert(key.clone(), value.clone());
    }
    if let Some((key, children)) = &item.children {
        object.insert(key.clone(), Value::Array(children.iter().map(item_json).collect()));
    }
    Value::Object(object)
}

fn items_xhtml(base: &str, items: &[Item]) -> String {
    page_xhtml(base, items, None)
}

fn page_xhtml(base: &str, items: &[Item], next: Option<&str>) -> String {
    let mut body = xhtml_head("RWS");
    body.push_str(&format!("<div class=\"state\"><a href=\"{}\" rel=\"self\"></a>", escape(base)));
    if let Some(next) = next {
        body.push_str(&format!("<a href=\"{}\" rel=\"next\"></a>", escape(next)));
    }
    body.push_str("<ul>");
    for item in items {
        body.push_str(&item_xhtml(item));
    }
    body.push_str("</ul></div>");
    body.push_str(XHTML_TAIL);
    body
}

/// One item as an XHTML `<li>`, on one line.
pub(crate) fn item_xhtml(item: &Item) -> String {
    let mut li = format!("<li class=\"{}\" title=\"{}\">", escape(&item.class), escape(&item.title));
    if let Some(link) = &item.link {
        li.push_str(&format!("<a href=\"{}\" rel=\"self\"></a>", escape(link)));
    }
    for (key, value) in &item.fields {
        li.push_str(&format!("<span class=\"{}\">{}</span>", escape(key), escape_text(value)));
    }
    if let Some((_, children)) = &item.children {
        li.push_str("<ul>");
        for child in children {
            li.push_str(&item_xhtml(child));
        }
        li.push_str("</ul>");
    }
    li.push_str("</li>");
    li
}

/// The start of an XHTML document, up to `<body>`, on one line.
pub(crate) fn xhtml_head(title: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?><html xmlns=\"http://www.w3.org/1999/xhtml\"><head>\
         <title>{}</title></head><body>",
        escape(title)
    )
}

pub(crate) const XHTML_TAIL: &str = "</body></html>";

/// Text made safe inside XHTML elements and attribute values.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            _ => out.push(xml_char(c)),
        }
    }
    out
}

/// Text made safe between XHTML tags: quotes stay as they are (a RAPID string
/// literal's quotes are part of its value, and clients read the text as it is).
pub(crate) fn escape_text(text: &str) -> String {
    let text = text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('\n', "&#10;");
    text.chars().map(xml_char).collect()
}

/// `c`, or U+FFFD for a character XML 1.0 cannot hold in any form (C0 controls but
/// tab, LF and CR; U+FFFE, U+FFFF): a client's XML parser refuses the whole answer
/// for one of them, and a request path can bring any (`%00` decodes to NUL).
fn xml_char(c: char) -> char {
    match c {
        '\t' | '\n' | '\r' => c,
        '\u{0}'..='\u{1f}' | '\u{fffe}' | '\u{ffff}' => '\u{fffd}',
        _ => c,
    }
}

/// A number as RWS writes it: integral values without a fraction (`"1"`, which the
/// Python client's `int()` accepts), others in Rust's shortest form.
pub(crate) fn number(value: f64) -> String {
    if value.is_finite() && value.fract() == 0.0 && value.abs() < 1e15 {
        format!("{}", value as i64)
    } else if value.abs() >= 1e9 {
        format!("{value:E}")
    } else {
        format!("{value}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_render_as_rws_json_and_one_line_xhtml() {
        let item = Item::new("pnl-ctrlstate", "ctrlstate").with("ctrlstate", "motoron");
        let json: Value = serde_json::from_str(&items_json("http://h/rw/panel/", std::slice::from_ref(&item))).unwrap();
        assert_eq!(json["_embedded"]["_state"][0]["_type"], "pnl-ctrlstate");
        assert_eq!(json["_embedded"]["_state"][0]["ctrlstate"], "motoron");
        assert_eq!(
            item_xhtml(&item),
            "<li class=\"pnl-ctrlstate\" title=\"ctrlstate\"><span class=\"ctrlstate\">motoron</span></li>"
        );
        assert!(!items_xhtml("b", &[item]).contains('\n'));
    }

    #[test]
    fn numbers_and_escapes() {
        assert_eq!(number(1.0), "1");
        assert_eq!(number(-3.0), "-3");
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(9e9), "9000000000");
        assert_eq!(escape("<a & \"b\">"), "&lt;a &amp; &quot;b&quot;&gt;");
    }

    /// Found by the `rws` fuzz target: a request path holding `%00` was echoed in the
    /// XHTML error body as a raw NUL, which no XML parser reads.
    #[test]
    fn characters_xml_cannot_hold_become_replacement_characters() {
        assert_eq!(escape("a\u{0}b\u{1b}c\td"), "a\u{fffd}b\u{fffd}c\td");
        assert_eq!(escape_text("x\u{7}\u{ffff}\r"), "x\u{fffd}\u{fffd}\r");
        assert_eq!(escape("line\nbreak"), "line&#10;break");
    }
}
