//! What the `rws` fuzz target is made of: the small system it boots, requests built
//! from the fuzzer's bytes, and the checks every answer must pass.
//!
//! Allowed statuses (the target's assertion): 200, 201, 204 (done), 400 (a request
//! the server cannot read), 401 (not logged in), 403 (refused: a path leaving a file
//! device, a right the user lacks), 404 (no such resource), 405 (a fixed route asked
//! with another method), 409 (the controller's state forbids it), 413 (a body too
//! large), 415 and 422 (a body of the wrong kind). Every request the fuzzer sends is
//! a client's, so a 5xx is a finding: 500 is the controller failing (an internal
//! error caught) or an I/O error blamed on the server, and 503 (busy) cannot happen
//! when requests come one at a time.

use arbitrary::{Result, Unstructured};
use axum::body::Body;
use axum::http::{header, HeaderMap, Method, Request, StatusCode};
use rapid_controller::api::{ClockPolicy, Session};
use rapid_controller::{Controller, TaskSpec};
use rapid_sema::SourceInput;

/// The program of the fuzzed system: persistents and variables of several types for
/// the symbol resources, a routine to set the program pointer to, and a main routine
/// that waits on `di1` and then idles (one-second waits keep the controller thread
/// from spinning when the fuzzer starts the program).
pub const PROGRAM: &str = "MODULE MainModule
  PERS num count := 0;
  PERS pos here := [1, 2, 3];
  VAR string name := \"abc\";
  VAR num list{3} := [1, 2, 3];
  CONST num limit := 3;
  PERS tooldata tGrip := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PROC other()
    count := 100;
  ENDPROC
  PROC main()
    WaitDI di1, 1;
    count := count + 1;
    SetDO do1, 1;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
";

/// The scratch folders' names: this prefix and the process id.
const ROOT_PREFIX: &str = "rapid-fuzz-rws-";

/// The scratch folder of the file devices (under the system's temporary folder, one
/// per process).
pub fn file_root() -> std::path::PathBuf {
    std::env::temp_dir().join(format!("{ROOT_PREFIX}{}", std::process::id()))
}

/// Removes the scratch folders of fuzzing processes that have ended. libFuzzer ends a
/// process with `exit`, which runs no destructor, so each process left its folder
/// behind; now the next one removes it, and one folder at most stays. Where `/proc`
/// does not say which processes live (not Linux), nothing is removed.
pub fn remove_stale_roots(temp: &std::path::Path) {
    let proc = std::path::Path::new("/proc");
    if !proc.join("self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(temp) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name.to_str().and_then(|name| name.strip_prefix(ROOT_PREFIX)) else { continue };
        if pid.parse::<u32>().is_ok_and(|pid| pid != std::process::id()) && !proc.join(pid).exists() {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

/// Starts a controller on [`PROGRAM`] with `di1` and `do1`, its file devices under
/// [`file_root`], paced at real time (waits sleep rather than spin).
pub fn boot() -> Result<rapid_serve::Controller, String> {
    remove_stale_roots(&std::env::temp_dir());
    let root = file_root();
    std::fs::create_dir_all(&root).map_err(|e| format!("{}: {e}", root.display()))?;
    let boot = rapid_serve::Boot {
        session: Box::new(move || session(root)),
        clock: ClockPolicy::Paced { rate: 1.0 },
        on_exit: None,
        on_tp_write: None,
    };
    rapid_serve::Controller::start(boot)
}

fn session(root: std::path::PathBuf) -> Result<Session, String> {
    let signals = [("di1", "signaldi", "DI"), ("do1", "signaldo", "DO")];
    let predefined = signals
        .iter()
        .map(|(n, ty, _)| rapid_sema::PredefinedData { name: (*n).to_owned(), type_name: (*ty).to_owned() })
        .collect();
    let options = rapid_sema::Options { predefined, ..rapid_sema::Options::default() };
    let mut loaded = rapid_controller::builtin_set::load_with(
        &[SourceInput::from_text("T_ROB1/MainModule.mod", PROGRAM)],
        "main",
        &options,
    )
    .map_err(|e| format!("{e:?}"))?;
    loaded.vm.resources_mut().devices.set_root(root);
    rapid_controller::bindings::sockets::of_mut(loaded.vm.resources_mut()).set_offline(true);
    let eio: String =
        signals.iter().map(|(n, _, kind)| format!("\n      -Name \"{n}\" -SignalType \"{kind}\"\n")).collect();
    let eio = rapid_config::eio::read(&rapid_config::parse(&format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{eio}")));
    let io = rapid_controller::boot::io_config::io_system(&eio)?;
    Ok(Session::new(Controller::new(vec![(TaskSpec::normal("T_ROB1", true), loaded)], Some(io))?))
}

/// An answer, its body read whole.
#[derive(Debug)]
pub struct Answer {
    pub status: StatusCode,
    pub headers: HeaderMap,
    pub body: Vec<u8>,
}

/// The request whose answer must always come: the controller state, as JSON.
pub fn plain_get(cookie: Option<&str>) -> Request<Body> {
    let mut builder = Request::get("/rw/panel/ctrlstate?json=1");
    if let Some(cookie) = cookie {
        builder = builder.header(header::COOKIE, cookie);
    }
    builder.body(Body::empty()).expect("a fixed request")
}

/// The Digest login answering `challenge` (a 401's answer) as the default user.
pub fn login_request(challenge: &Answer) -> Option<Request<Body>> {
    let text = challenge.headers.get(header::WWW_AUTHENTICATE)?.to_str().ok()?;
    let uri = "/rw/panel/ctrlstate?json=1";
    let auth = rapid_serve::digest_authorization(text, rapid_serve::DEFAULT_USER, "GET", uri, "0a4f113b")?;
    Request::get(uri).header(header::AUTHORIZATION, auth).body(Body::empty()).ok()
}

/// The session cookies a login's answer sets, as one `Cookie` header.
pub fn cookies_of(answer: &Answer) -> Option<String> {
    let cookies: Vec<&str> =
        answer.headers.get_all(header::SET_COOKIE).iter().filter_map(|v| v.to_str().ok()?.split(';').next()).collect();
    (!cookies.is_empty()).then(|| cookies.join("; "))
}

/// Path segments RWS knows, so that most generated paths reach a resource.
const SEGMENTS: &[&str] = &[
    "rw",
    "panel",
    "ctrlstate",
    "opmode",
    "speedratio",
    "lock",
    "rapid",
    "execution",
    "tasks",
    "T_ROB1",
    "pcp",
    "symbol",
    "symbols",
    "data",
    "properties",
    "RAPID",
    "MainModule",
    "count",
    "here",
    "name",
    "list",
    "limit",
    "tGrip",
    "main",
    "other",
    "modules",
    "iosystem",
    "signals",
    "devices",
    "networks",
    "di1",
    "do1",
    "Local",
    "DRV_1",
    "motionsystem",
    "mechunits",
    "ROB_1",
    "robtarget",
    "jointtarget",
    "elog",
    "0",
    "1",
    "cfg",
    "EIO",
    "EIO_SIGNAL",
    "SYS",
    "MOC",
    "instances",
    "fileservice",
    "$HOME",
    "$TEMP",
    "HOME:",
    "a.txt",
    "dir",
    "..",
    ".",
    "subscription",
    "users",
    "rmmp",
    "poll",
    "mastership",
    "edit",
    "motion",
    "dipc",
    "q1",
    "logout",
    "ctrl",
    "system",
    "clock",
    "options",
    "products",
    "pendant",
    "api",
    "screen",
    "answer",
    "arms",
    "program",
    "%C3%A4",
    "%00",
    "%FF",
    "%2F",
    "a%20b",
];

/// Query and form keys and values RWS reads.
const KEYS: &[&str] = &[
    "json",
    "action",
    "resource",
    "value",
    "start",
    "limit",
    "task",
    "tool",
    "wobj",
    "coordinate",
    "lvalue",
    "mode",
    "opmode",
    "ctrl-state",
    "speed-ratio",
    "cycle",
    "regain",
    "execmode",
    "condition",
    "stopatbp",
    "alltaskbytsp",
    "routine",
    "userlevel",
    "module",
    "modulepath",
    "replace",
    "symtyp",
    "blockurl",
    "stopmode",
    "username",
    "privilege",
    "dipc-queue-name",
    "dipc-data",
    "dipc-userdef",
    "dipc-msgtype",
    "dipc-cmd",
    "dipc-max-msg-size",
    "dipc-src-queue-name",
    "fs-newname",
    "id",
    "answer",
    "lang",
    "elogseq",
    "1",
    "2",
    "3",
];
const VALUES: &[&str] = &[
    "1",
    "0",
    "-1",
    "1e400",
    "NaN",
    "true",
    "TRUE",
    "start",
    "stop",
    "set",
    "resetpp",
    "setctrlstate",
    "setopmode",
    "setspeedratio",
    "setcycle",
    "set-pp-routine",
    "loadmod",
    "unloadmod",
    "show",
    "request",
    "release",
    "cancel",
    "create",
    "clear",
    "clearall",
    "search-symbols",
    "module-text",
    "dipc-create",
    "dipc-send",
    "dipc-read",
    "motoron",
    "motoroff",
    "AUTO",
    "MANR",
    "MANF",
    "forever",
    "once",
    "asis",
    "continue",
    "stop",
    "main",
    "other",
    "T_ROB1",
    "MainModule",
    "HOME:/a.mod",
    "$HOME/a.mod",
    "[1,2,3]",
    "\"x\"",
    "5",
    "100",
    "101",
    "4294967296",
    "/rw/panel/ctrlstate",
    "/rw/iosystem/signals/Local/DRV_1/di1;state",
    "/rw/rapid/symbol/data/RAPID/T_ROB1/MainModule/count;value",
    "/rw/elog/0",
    "edit",
    "motion",
    "PERS",
    "VAR",
    "CONST",
    "num",
    "ä",
    "",
];

/// Text from the fuzzer: a known word mostly, arbitrary text sometimes.
fn word(u: &mut Unstructured, known: &[&str]) -> Result<String> {
    if u.ratio(1u8, 5)? {
        let len = u.int_in_range(0..=24usize)?;
        let bytes = u.bytes(len.min(u.len()))?;
        Ok(String::from_utf8_lossy(bytes).into_owned())
    } else {
        Ok(u.choose(known)?.to_string())
    }
}

/// Percent-encodes what a URI cannot hold as it is (a URI's text must parse).
fn encode(text: &str, keep: &'static percent_encoding::AsciiSet) -> String {
    percent_encoding::utf8_percent_encode(text, keep).to_string()
}

const PATH_SET: &percent_encoding::AsciiSet = &percent_encoding::CONTROLS
    .add(b' ')
    .add(b'"')
    .add(b'#')
    .add(b'<')
    .add(b'>')
    .add(b'?')
    .add(b'`')
    .add(b'{')
    .add(b'}')
    .add(b'/');
const QUERY_SET: &percent_encoding::AsciiSet = &PATH_SET.add(b'&').add(b'=').add(b'+');

/// One request from the fuzzer's bytes, with the session `cookie` most of the time.
pub fn request(u: &mut Unstructured, cookie: Option<&str>) -> Result<Request<Body>> {
    let method = match u.int_in_range(0..=9u8)? {
        0..=3 => Method::GET,
        4..=6 => Method::POST,
        7 => Method::PUT,
        8 => Method::DELETE,
        _ => u.choose(&[Method::HEAD, Method::OPTIONS, Method::PATCH])?.clone(),
    };
    let mut path = String::new();
    for _ in 0..u.int_in_range(0..=8u8)? {
        path.push('/');
        let segment = word(u, SEGMENTS)?;
        // Known segments may hold escapes already; arbitrary text is encoded.
        path.push_str(&if SEGMENTS.contains(&segment.as_str()) { segment } else { encode(&segment, PATH_SET) });
    }
    if path.is_empty() || u.ratio(1u8, 8)? {
        path.push('/');
    }
    // A symbol's attribute: `…/count;value`.
    if u.ratio(1u8, 6)? {
        path.push(';');
        path.push_str(u.choose(&["value", "state", "properties", "a", ""])?);
    }
    let mut query = Vec::new();
    if u.ratio(2u8, 3)? {
        query.push("json=1".to_owned());
    }
    for _ in 0..u.int_in_range(0..=3u8)? {
        query.push(format!("{}={}", encode(&word(u, KEYS)?, QUERY_SET), encode(&word(u, VALUES)?, QUERY_SET)));
    }
    let uri = if query.is_empty() { path } else { format!("{path}?{}", query.join("&")) };
    let mut builder = Request::builder().method(method).uri(uri.as_str());
    if let Some(cookie) = cookie.filter(|_| u.ratio(7u8, 8).unwrap_or(true)) {
        builder = builder.header(header::COOKIE, cookie);
    }
    if u.ratio(1u8, 8)? {
        builder = builder.header(header::HOST, encode(&word(u, &["robot:80", "[::1]", "a\"b<c>"])?, PATH_SET));
    }
    let body = match u.int_in_range(0..=3u8)? {
        0 => Vec::new(),
        1 => {
            let len = u.int_in_range(0..=64usize)?.min(u.len());
            u.bytes(len)?.to_vec()
        }
        _ => {
            builder = builder.header(header::CONTENT_TYPE, "application/x-www-form-urlencoded");
            let mut fields = Vec::new();
            for _ in 0..u.int_in_range(0..=4u8)? {
                fields.push(format!("{}={}", encode(&word(u, KEYS)?, QUERY_SET), encode(&word(u, VALUES)?, QUERY_SET)));
            }
            fields.join("&").into_bytes()
        }
    };
    if u.ratio(1u8, 16)? {
        // A length that does not match the body (or is no number).
        builder =
            builder.header(header::CONTENT_LENGTH, word(u, &["0", "100000000", "x", "-1"])?.replace(['\r', '\n'], ""));
    }
    // A URI the fuzzer wrote may still not parse: that is no request (hyper would
    // refuse it before the router sees it).
    builder.body(Body::from(body)).map_err(|_| arbitrary::Error::IncorrectFormat)
}

/// Checks one answer: an allowed status (see the module's doc), and a body a client
/// parses. `what` names the request in a failure.
pub fn check_answer(what: &str, json: bool, answer: &Answer) {
    let status = answer.status.as_u16();
    assert!(
        matches!(status, 200 | 201 | 204 | 400 | 401 | 403 | 404 | 405 | 409 | 413 | 415 | 422),
        "{what}: status {status}: {}",
        String::from_utf8_lossy(&answer.body)
    );
    if answer.body.is_empty() {
        return;
    }
    let ctype = answer.headers.get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).unwrap_or("");
    if ctype.starts_with("application/octet-stream") || !(ctype.contains("json") || ctype.contains("xhtml")) {
        // A file's bytes, the pendant's pages and axum's own plain-text refusals.
        return;
    }
    let text = std::str::from_utf8(&answer.body).unwrap_or_else(|e| panic!("{what}: the body is not UTF-8: {e}"));
    if ctype.contains("json") {
        if let Err(e) = serde_json::from_str::<serde_json::Value>(text) {
            panic!("{what}: the JSON body does not parse ({e}): {text}");
        }
    } else {
        assert!(!json || status == 401, "{what}: json=1 asked, {ctype} answered: {text}");
        if let Err(why) = well_formed_xml(text) {
            panic!("{what}: the XHTML body is not well-formed ({why}): {text}");
        }
    }
}

/// Whether `text` is well-formed XML as far as a client's parser cares: tags closed
/// in order, attribute values quoted, `&` only in entity and character references,
/// no character XML forbids (C0 controls but tab, LF and CR).
pub fn well_formed_xml(text: &str) -> std::result::Result<(), String> {
    if let Some(c) =
        text.chars().find(|&c| (c < ' ' && !matches!(c, '\t' | '\n' | '\r')) || c == '\u{FFFE}' || c == '\u{FFFF}')
    {
        return Err(format!("the character U+{:04X}", c as u32));
    }
    let mut open: Vec<&str> = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find(['<', '&']) {
        check_text(&rest[..at])?;
        rest = &rest[at..];
        if rest.starts_with('&') {
            let end = rest.find(';').ok_or("an `&` without `;`")?;
            check_reference(&rest[1..end])?;
            rest = &rest[end + 1..];
            continue;
        }
        let end = tag_end(rest).ok_or("a tag without `>`")?;
        let tag = &rest[1..end];
        rest = &rest[end + 1..];
        if tag.starts_with('?') || tag.starts_with('!') {
            continue;
        }
        if let Some(name) = tag.strip_prefix('/') {
            match open.pop() {
                Some(top) if top == name.trim() => {}
                top => return Err(format!("`</{name}>` closes {top:?}")),
            }
            continue;
        }
        let self_closing = tag.ends_with('/');
        let name = tag.split([' ', '/']).next().unwrap_or("");
        if name.is_empty() {
            return Err("a tag without a name".into());
        }
        check_attributes(&tag[name.len()..])?;
        if !self_closing {
            open.push(name);
        }
    }
    check_text(rest)?;
    match open.last() {
        Some(name) => Err(format!("`<{name}>` is not closed")),
        None => Ok(()),
    }
}

/// The end of the tag at the start of `text`: its `>` outside quoted values.
fn tag_end(text: &str) -> Option<usize> {
    let mut quote = None;
    for (i, c) in text.char_indices().skip(1) {
        match (quote, c) {
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), _) if q == c => quote = None,
            (None, '>') => return Some(i),
            (None, '<') => return None,
            _ => {}
        }
    }
    None
}

fn check_text(text: &str) -> std::result::Result<(), String> {
    match text.contains("]]>") {
        true => Err("`]]>` in text".into()),
        false => Ok(()),
    }
}

fn check_reference(name: &str) -> std::result::Result<(), String> {
    let ok = match name.strip_prefix('#') {
        Some(num) => {
            let value = match num.strip_prefix('x') {
                Some(hex) => u32::from_str_radix(hex, 16).ok(),
                None => num.parse::<u32>().ok(),
            };
            value.and_then(char::from_u32).is_some_and(|c| c >= ' ' || matches!(c, '\t' | '\n' | '\r'))
        }
        None => matches!(name, "amp" | "lt" | "gt" | "quot" | "apos"),
    };
    if ok {
        Ok(())
    } else {
        Err(format!("the reference `&{name};`"))
    }
}

/// ` a="x" b='y'` (and a trailing `/`): each value quoted, `<` and a bare `&` nowhere.
fn check_attributes(text: &str) -> std::result::Result<(), String> {
    let mut rest = text.trim_end_matches('/').trim();
    while !rest.is_empty() {
        let eq = rest.find('=').ok_or_else(|| format!("an attribute without a value: {rest}"))?;
        let value = rest[eq + 1..].trim_start();
        let quote = value.chars().next().filter(|c| matches!(c, '"' | '\'')).ok_or("an unquoted attribute value")?;
        let end = value[1..].find(quote).ok_or("an attribute value not closed")? + 1;
        let inner = &value[1..end];
        if inner.contains('<') {
            return Err(format!("`<` in an attribute value: {inner}"));
        }
        let mut refs = inner;
        while let Some(at) = refs.find('&') {
            let semi = refs[at..].find(';').ok_or("an `&` without `;` in an attribute")? + at;
            check_reference(&refs[at + 1..semi])?;
            refs = &refs[semi + 1..];
        }
        rest = value[end + 1..].trim_start();
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_xml_check_accepts_what_rws_writes_and_refuses_breakage() {
        let page = "<?xml version=\"1.0\" encoding=\"utf-8\"?><html xmlns=\"x\"><head><title>E</title></head>\
                    <body><li class=\"a\" title=\"&quot;b&quot;\"><a href=\"h\" rel=\"self\"></a>\
                    <span class=\"k\">\"1 &lt; 2\"&#10;</span></li></body></html>";
        assert_eq!(well_formed_xml(page), Ok(()));
        assert!(well_formed_xml("<a><b></a></b>").is_err());
        assert!(well_formed_xml("<a>1 & 2</a>").is_err());
        assert!(well_formed_xml("<a t=\"<\"></a>").is_err());
        assert!(well_formed_xml("<a>\u{1}</a>").is_err());
        assert!(well_formed_xml("<a>&#1;</a>").is_err());
        assert!(well_formed_xml("<a>").is_err());
    }

    #[test]
    fn the_scratch_folders_of_ended_processes_are_removed_and_live_ones_kept() {
        let temp = std::env::temp_dir().join(format!("rapid-fuzz-rws-test-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&temp);
        // No process has the largest id (Linux's pids stay far below it); this one lives.
        let ended = temp.join(format!("{ROOT_PREFIX}{}", u32::MAX));
        let live = temp.join(format!("{ROOT_PREFIX}{}", std::process::id()));
        let other = temp.join(format!("{ROOT_PREFIX}notapid"));
        for folder in [&ended, &live, &other] {
            std::fs::create_dir_all(folder).expect("a scratch folder");
        }
        std::fs::write(ended.join("left.txt"), "x").expect("a file left behind");
        remove_stale_roots(&temp);
        let on_linux = std::path::Path::new("/proc/self").exists();
        assert_eq!(ended.exists(), !on_linux);
        assert!(live.exists() && other.exists());
        let _ = std::fs::remove_dir_all(&temp);
    }

    #[test]
    fn generated_requests_are_built() {
        let bytes: Vec<u8> = (0..4096u32).map(|i| (i.wrapping_mul(2654435761) >> 13) as u8).collect();
        let mut u = Unstructured::new(&bytes);
        let mut built = 0;
        for _ in 0..50 {
            if request(&mut u, Some("a=b")).is_ok() {
                built += 1;
            }
        }
        assert!(built >= 25, "only {built} of 50 requests were built");
    }
}
